"""Volumes apart from each other, in any order of AddVolume, against the exact reference.

VTK draws a renderer's volumes in the order they were added, each over what is drawn: a far
volume added after a near one covered it (spx_vistrails twice along the view, the near one
added first: RMSE 1.41, max 23/255 before). The first of this module's volumes that VTK draws
now draws all of them, farthest first (vtkTiledRayCastVolumeGroup::RenderInDepthOrder). Each
scene is compared with the reference renderer's scene of the same volumes
(vtkTetReferenceRenderer::AddVolume), within the scene tests' bounds (RMSE 0.75, max 2):
near added first, three in a scrambled order, seen from behind, the camera inside one, a
parallel projection, a fragment-pipeline volume among them (it cannot join a group but is
ordered), two volumes of one mapper, and a group of two overlapping volumes with one apart.
VTK's projected tetrahedra in the same renderer still draw (not compared: not exact).
"""
import unittest

from vtkmodules.vtkCommonCore import vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow, vtkVolume
from vtkmodules.vtkRenderingVolume import vtkProjectedTetrahedraMapper
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL implementations)
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401  (the projected tetrahedra's)

from tiledraycast import vtkTetReferenceRenderer, vtkTetReferenceVolume
from tiledraycast import vtkTiledRayCastVolumeMapper
from tiledraycast_testing import main, read_mesh, volume_property

SIZE = 160
BLUE_RED = ((0.0, (0.1, 0.3, 1.0)), (1.0, (1.0, 0.2, 0.1)))
GREEN_YELLOW = ((0.0, (0.2, 1.0, 0.2)), (1.0, (1.0, 1.0, 0.1)))
OPACITIES = ((0.0, 0.05), (1.0, 0.6))
M = vtkTiledRayCastVolumeMapper


class TestTiledRayCastVolumeOrder(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.grid = read_mesh("spx_vistrails.vtu")
        cls.length = cls.grid.GetLength()
        cls.range = cls.grid.GetPointData().GetScalars().GetRange()

    def render(self, shifts, order, position, focal, pipelines=None, shared=False,
               parallel=False, extra=None):
        """Copies of the mesh at `shifts` (in mesh lengths along x, or (x, y, z)), added in
        `order`; the camera at `position` looking at `focal` (mesh lengths). Returns RMSE and
        max against the reference, and the volumes."""
        window = vtkRenderWindow()
        window.SetOffScreenRendering(1)
        window.SetMultiSamples(0)
        window.SetSize(SIZE, SIZE)
        renderer = vtkRenderer()
        renderer.SetBackground(26 / 255.0, 26 / 255.0, 38 / 255.0)
        window.AddRenderer(renderer)
        volumes = []
        mapper = None
        for k, shift in enumerate(shifts):
            if not shared or mapper is None:
                mapper = M()
                mapper.SetInputData(self.grid)
                if pipelines:
                    mapper.SetPipeline(pipelines[k])
            prop = volume_property(self.range, BLUE_RED if k % 2 == 0 else GREEN_YELLOW,
                                   OPACITIES, 0.1 * self.length)
            volume = vtkVolume()
            volume.SetMapper(mapper)
            volume.SetProperty(prop)
            shift = shift if isinstance(shift, tuple) else (shift, 0.0, 0.0)
            volume.SetPosition(*[s * self.length for s in shift])
            volumes.append(volume)
        for k in order:
            renderer.AddVolume(volumes[k])
        if extra:
            renderer.AddVolume(extra)
        camera = renderer.GetActiveCamera()
        camera.SetPosition(*[p * self.length for p in position])
        camera.SetFocalPoint(*[p * self.length for p in focal])
        camera.SetViewUp(0.0, 0.0, 1.0)
        if parallel:
            camera.ParallelProjectionOn()
            camera.SetParallelScale(1.2 * self.length)
        renderer.ResetCameraClippingRange()
        window.Render()
        for volume in volumes:
            self.assertTrue(volume.GetMapper().GetStatistics().GetRendered())
        if extra:
            return None, None, volumes
        pixels = vtkUnsignedCharArray()
        window.GetPixelData(0, 0, SIZE - 1, SIZE - 1, 0, pixels, 0)
        reference = vtkTetReferenceRenderer()
        reference.SetCamera(camera)
        reference.SetImageSize(SIZE, SIZE)
        for volume in volumes:
            added = vtkTetReferenceVolume()
            added.SetInputData(self.grid)
            added.SetVolumeProperty(volume.GetProperty())
            added.SetVolume(volume)
            reference.AddVolume(added)
        self.assertTrue(reference.Render())
        image = vtkImageData()
        reference.ConvertToUnsignedChar(reference.GetOutput(), renderer.GetBackground(), image)
        exact = image.GetPointData().GetScalars()
        n = pixels.GetNumberOfValues()
        diffs = [abs(pixels.GetValue(i) - exact.GetValue(i)) for i in range(n)]
        return (sum(d * d for d in diffs) / n) ** 0.5, max(diffs), volumes

    def check(self, name, *args, **kwargs):
        rmse, worst, volumes = self.render(*args, **kwargs)
        grouped = [v.GetMapper().GetStatistics().GetNumberOfGroupedVolumes() for v in volumes]
        print("%s: RMSE %.3f, max %d (grouped volumes %s)" % (name, rmse, worst, grouped))
        self.assertLessEqual(rmse, 0.75, name)
        self.assertLessEqual(worst, 2, name)
        return grouped

    def test_scenes(self):
        self.check("near added first", [0, 1.5], [0, 1], (-2, 0.3, 0.2), (2, 0, 0))
        self.check("far added first", [0, 1.5], [1, 0], (-2, 0.3, 0.2), (2, 0, 0))
        self.check("three, scrambled", [0, 1.5, 3.0], [1, 2, 0], (-2, 0.3, 0.2), (4, 0, 0))
        self.check("three, from behind", [0, 1.5, 3.0], [0, 1, 2], (6, 0.3, 0.2), (0, 0, 0))
        self.check("camera inside the near one", [0, 1.5], [0, 1], (0, 0, 0), (3, 0, 0))
        self.check("camera inside the far one, looking back", [0, 1.5], [0, 1], (1.5, 0, 0),
                   (-3, 0, 0))
        self.check("parallel projection", [0, 1.5], [0, 1], (-2, 0.3, 0.2), (2, 0, 0),
                   parallel=True)
        self.check("a fragment-pipeline volume among them", [0, 1.5, 3.0], [0, 1, 2],
                   (-2, 0.3, 0.2), (4, 0, 0), pipelines=[M.FRAGMENT_PIPELINE,
                                                         M.COMPUTE_PIPELINE,
                                                         M.FRAGMENT_PIPELINE])
        self.check("two volumes of one mapper", [0, 1.5], [0, 1], (-2, 0.3, 0.2), (2, 0, 0),
                   shared=True)
        grouped = self.check("a group of two with one apart, the group nearest",
                             [(0, 0, 0), (0.3, 0.2, 0.1), (1.8, 0, 0)], [0, 1, 2],
                             (-2, 0.3, 0.2), (3, 0, 0))
        self.assertEqual(grouped, [2, 2, 1])

    def test_with_projected_tetrahedra(self):
        """VTK's projected tetrahedra in the same renderer, added between ours: all draw."""
        prop = volume_property(self.range, BLUE_RED, OPACITIES, 0.1 * self.length)
        theirs = vtkVolume()
        theirs.SetMapper(vtkProjectedTetrahedraMapper())
        theirs.GetMapper().SetInputData(self.grid)
        theirs.SetProperty(prop)
        theirs.SetPosition(0.0, 1.5 * self.length, 0.0)
        self.render([0, 1.5], [1, 0], (-2, 0.3, 0.2), (2, 0, 0), extra=theirs)


if __name__ == "__main__":
    main()
