"""The exact reference renderer and its integrator, used from Debian's /usr/bin/python3.

Renders a small image of spx_vistrails.vtu and checks it against what must hold (coverage,
alpha in [0, 1), premultiplied colours not above alpha, tetrahedra counted), a single
tetrahedron of constant scalar against its closed form, and the integrator's closed form for
constant attenuation.
"""
import math
import unittest

from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkFloatArray, vtkPoints
from vtkmodules.vtkCommonDataModel import VTK_TETRA, vtkImageData, vtkUnstructuredGrid
from vtkmodules.vtkRenderingCore import vtkCamera
from tiledraycast import vtkTetRayIntegrator, vtkTetReferenceRenderer, vtkTetReferenceVolume
from tiledraycast_testing import main, read_mesh, volume_property

# Blue, green at the middle, red; opacity 0.05 to 0.9, over the scalar range.
COLORS = ((0.0, (0.1, 0.2, 1.0)), (0.5, (0.2, 1.0, 0.3)), (1.0, (1.0, 0.3, 0.1)))
OPACITIES = ((0.0, 0.05), (1.0, 0.9))


def constant(value):
    """A ramp that is `value` over the whole range."""
    return ((0.0, value), (1.0, value))


def unit_tetrahedron():
    """The tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1), of constant scalar 0.5."""
    points = vtkPoints()
    points.SetDataTypeToDouble()
    for p in ((0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)):
        points.InsertNextPoint(p)
    grid = vtkUnstructuredGrid()
    grid.SetPoints(points)
    grid.InsertNextCell(VTK_TETRA, 4, [0, 1, 2, 3])
    scalars = vtkDoubleArray()
    for _ in range(4):
        scalars.InsertNextValue(0.5)
    grid.GetPointData().SetScalars(scalars)
    return grid


def camera_down_z():
    """Looking down -z at the unit square with a parallel projection: through the unit
    tetrahedron, the chord at (x, y) is 1 - x - y."""
    camera = vtkCamera()
    camera.ParallelProjectionOn()
    camera.SetParallelScale(0.5)
    camera.SetFocalPoint(0.5, 0.5, 0.0)
    camera.SetPosition(0.5, 0.5, 5.0)
    camera.SetViewUp(0, 1, 0)
    camera.SetClippingRange(1.0, 10.0)
    return camera


def pixel_chords(n):
    """(pixel index, chord through the unit tetrahedron) of every pixel of an n x n image seen
    with camera_down_z()."""
    for j in range(n):
        for i in range(n):
            x, y = (i + 0.5) / n, (j + 0.5) / n
            yield i + n * j, max(0.0, 1.0 - x - y)


class TestReferenceRendererPython(unittest.TestCase):
    def test_dataset(self):
        grid = read_mesh("spx_vistrails.vtu")
        b = grid.GetBounds()
        diag = math.sqrt((b[1] - b[0]) ** 2 + (b[3] - b[2]) ** 2 + (b[5] - b[4]) ** 2)
        center = [(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2]
        camera = vtkCamera()
        camera.SetFocalPoint(center)
        camera.SetPosition(center[0] + 0.8 * diag, center[1] + 0.4 * diag, center[2] + 1.1 * diag)
        camera.SetViewUp(0, 1, 0)
        camera.SetClippingRange(0.1 * diag, 5 * diag)

        renderer = vtkTetReferenceRenderer()
        renderer.SetInputData(grid)
        renderer.SetVolumeProperty(volume_property(grid.GetPointData().GetScalars().GetRange(),
                                                   COLORS, OPACITIES, diag / 15))
        renderer.SetCamera(camera)
        renderer.SetImageSize(64, 48)
        self.assertEqual(renderer.Render(), 1)
        self.assertEqual(renderer.GetNumberOfTetrahedra(), grid.GetNumberOfCells())

        image = renderer.GetOutput()
        self.assertEqual(image.GetDimensions(), (64, 48, 1))
        rgba = image.GetPointData().GetArray("RGBA")
        counts = image.GetPointData().GetArray("NumberOfTets")
        covered = 0
        for p in range(64 * 48):
            r, g, bl, a = rgba.GetTuple4(p)
            self.assertTrue(0.0 <= a < 1.0)
            for c in (r, g, bl):
                # Colours of the transfer function are <= 1: premultiplied values <= alpha.
                self.assertTrue(-1e-12 <= c <= a + 1e-6)
            n = counts.GetValue(p)
            self.assertEqual(n > 0, a > 0)
            covered += a > 0
        self.assertGreater(covered, 200)

        rgb8 = vtkImageData()
        vtkTetReferenceRenderer.ConvertToUnsignedChar(image, (0.0, 0.0, 0.0), rgb8)
        stats = [0.0, 0.0, 0.0]
        self.assertEqual(vtkTetReferenceRenderer.CompareImages(image, rgb8, stats), 1)
        self.assertLessEqual(stats[2], 0.5 + 1e-3)  # rounding to 8 bits only

    def test_single_tetrahedron(self):
        grid = unit_tetrahedron()
        # Looking down -z with a parallel projection: the chord at (x, y) is 1 - x - y.
        camera = camera_down_z()
        tau = 1.7
        prop = volume_property((0.0, 1.0), COLORS, constant(tau), 1.0)
        renderer = vtkTetReferenceRenderer()
        renderer.SetInputData(grid)
        renderer.SetVolumeProperty(prop)
        renderer.SetCamera(camera)
        renderer.SetImageSize(16, 16)
        renderer.DoublePrecisionOutputOn()
        self.assertEqual(renderer.Render(), 1)
        rgba = renderer.GetOutput().GetPointData().GetArray("RGBA")
        for pixel, chord in pixel_chords(16):
            alpha = rgba.GetComponent(pixel, 3)
            self.assertAlmostEqual(alpha, -math.expm1(-tau * chord), delta=1e-12)

    def test_integrator(self):
        prop = volume_property((0.0, 1.0), COLORS, constant(0.8), 2.0)
        integrator = vtkTetRayIntegrator()
        self.assertEqual(integrator.Initialize(prop), 1)
        rgba = [0.0, 0.0, 0.0, 0.0]
        integrator.Integrate(0.2, 0.7, 1.5, rgba)
        self.assertAlmostEqual(rgba[3], -math.expm1(-0.4 * 1.5), delta=1e-14)
        self.assertGreaterEqual(integrator.GetNumberOfNodes(), 3)
        nodes = [integrator.GetNode(i) for i in range(integrator.GetNumberOfNodes())]
        self.assertEqual(nodes, sorted(nodes))


    def test_scene(self):
        """Two overlapping tetrahedra (AddVolume) and a translucent layer in front of them."""
        grid = unit_tetrahedron()
        camera = camera_down_z()

        def prop(tau, rgb):
            return volume_property((0.0, 1.0), constant(rgb), constant(tau))

        renderer = vtkTetReferenceRenderer()
        renderer.SetCamera(camera)
        renderer.SetImageSize(16, 16)
        renderer.DoublePrecisionOutputOn()
        first = renderer.AddVolume(grid, prop(1.2, (1.0, 0.0, 0.0)))
        self.assertIsInstance(first, vtkTetReferenceVolume)
        second = vtkTetReferenceVolume()
        second.SetInputData(grid)
        second.SetVolumeProperty(prop(0.3, (0.0, 0.0, 1.0)))
        renderer.AddVolume(second)
        self.assertEqual(renderer.GetNumberOfAddedVolumes(), 2)
        layer_rgba = vtkDoubleArray()
        layer_rgba.SetNumberOfComponents(4)
        layer_depth = vtkFloatArray()
        for _ in range(16 * 16):
            layer_rgba.InsertNextTuple4(0.0, 0.25, 0.0, 0.5)
            layer_depth.InsertNextValue(0.01)  # in front of the tetrahedron
        renderer.AddTranslucentLayer(layer_rgba, layer_depth)
        self.assertEqual(renderer.Render(), 1)
        rgba = renderer.GetOutput().GetPointData().GetArray("RGBA")
        for pixel, chord in pixel_chords(16):
            a = -math.expm1(-1.5 * chord)
            expected = (1.2 / 1.5 * 0.5 * a, 0.25, 0.3 / 1.5 * 0.5 * a, 1 - 0.5 * (1 - a))
            for k in range(4):
                self.assertAlmostEqual(rgba.GetComponent(pixel, k), expected[k], delta=1e-12)


if __name__ == "__main__":
    main()
