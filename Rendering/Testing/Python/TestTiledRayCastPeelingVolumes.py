"""Several volumes inside VTK's depth peeling, against the exact reference.

With vtkRenderer::UseDepthPeelingForVolumes, VTK's dual depth peeling draws every volume once
per stage of its peeling (before the peels, each peel, the remainder) and blends what each
returns into its own targets with MAX: two volumes meeting one pixel's range in one stage came
out as the brighter of the two, not one in front of the other. Overlapping volumes were drawn
apart (not mixed), and volumes apart were not ordered (issue 26, item 2). Now the first of this
module's volumes that a stage draws composes all of them there: each group of overlapping
volumes in one traversal between the stage's depths, the groups and lone volumes in depth
order (vtkTiledRayCastVolumeGroup), and the whole returned to the pass once.

Each scene is compared with the reference renderer's scene of the same volumes and the
translucent surfaces as layers of fragments (vtkTetReferenceRenderer::AddTranslucentLayer, each
surface's front- and back-facing fragments read from the depth buffer), within the bounds of
TestTiledRayCastTranslucent (the pass keeps its colours in 8-bit textures between peels):
RMSE 1.0, max 4 (1/255).
"""
import unittest

from vtkmodules.vtkCommonCore import vtkFloatArray, vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow, vtkVolume)
from vtkmodules.vtkRenderingVolume import vtkProjectedTetrahedraMapper
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL implementations)
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401  (the projected tetrahedra's)

from tiledraycast import vtkTetReferenceRenderer, vtkTetReferenceVolume
from tiledraycast import vtkTiledRayCastVolumeMapper
from tiledraycast_testing import main, read_mesh, volume_property

SIZE = 128
BACKGROUND = (26 / 255.0, 26 / 255.0, 38 / 255.0)
BLUE_RED = ((0.0, (0.1, 0.3, 1.0)), (1.0, (1.0, 0.2, 0.1)))
GREEN_YELLOW = ((0.0, (0.2, 1.0, 0.2)), (1.0, (1.0, 1.0, 0.1)))
OPACITIES = ((0.0, 0.05), (1.0, 0.6))
M = vtkTiledRayCastVolumeMapper
# The bounds of TestTiledRayCastTranslucent: RGBA8 rounding of the peels.
RMSE_BOUND = 1.0
MAX_BOUND = 4


def flat_actor(source, color, opacity):
    """An actor of `source` whose fragments are exactly `color` at `opacity` (ambient only)."""
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    prop = actor.GetProperty()
    prop.SetAmbient(1.0)
    prop.SetDiffuse(0.0)
    prop.SetSpecular(0.0)
    prop.SetAmbientColor(*color)
    prop.SetColor(*color)
    prop.SetOpacity(opacity)
    return actor


class Scene:
    """Copies of a mesh at `shifts` (mesh lengths), added in `order`, with a translucent sphere
    (centre and radius in mesh lengths, from the mesh's centre), a translucent plane and, where
    asked, an opaque sphere, in a renderer with depth peeling for volumes."""

    def __init__(self, grid, shifts, order, mappers=None, peels=8,
                 sphere=((0.45, 0.05, 0), 0.45), opaque=None):
        self.grid = grid
        length = grid.GetLength()
        scalar_range = grid.GetPointData().GetScalars().GetRange()
        self.window = vtkRenderWindow()
        self.window.SetOffScreenRendering(1)
        self.window.SetMultiSamples(0)
        self.window.SetAlphaBitPlanes(1)
        self.window.SetSize(SIZE, SIZE)
        self.renderer = vtkRenderer()
        self.renderer.SetBackground(*BACKGROUND)
        self.window.AddRenderer(self.renderer)
        self.volumes = []
        for k, shift in enumerate(shifts):
            mapper = mappers[k]() if mappers else M()
            mapper.SetInputData(grid)
            prop = volume_property(scalar_range, BLUE_RED if k % 2 == 0 else GREEN_YELLOW,
                                   OPACITIES, 0.04 * length)
            volume = vtkVolume()
            volume.SetMapper(mapper)
            volume.SetProperty(prop)
            volume.SetPosition(*[s * length for s in shift])
            self.volumes.append(volume)
        for k in order:
            self.renderer.AddVolume(self.volumes[k])
        c = grid.GetCenter()
        self.sphere = vtkSphereSource()
        at, radius = sphere
        self.sphere.SetCenter(*[c[i] + at[i] * length for i in range(3)])
        self.sphere.SetRadius(radius * length)
        self.sphere.SetThetaResolution(48)
        self.sphere.SetPhiResolution(32)
        self.plane = vtkPlaneSource()
        self.plane.SetOrigin(c[0] - length, c[1] - 0.6 * length, c[2] - length)
        self.plane.SetPoint1(c[0] + 3 * length, c[1] - 0.6 * length, c[2] - length)
        self.plane.SetPoint2(c[0] - length, c[1] + 0.6 * length, c[2] + length)
        self.surfaces = [(flat_actor(self.sphere, (0.2, 0.6, 1.0), 0.45), 0.45),
                         (flat_actor(self.plane, (1.0, 0.85, 0.3), 0.3), 0.3)]
        for actor, _ in self.surfaces:
            self.renderer.AddActor(actor)
        self.opaque = None
        if opaque:
            at, radius = opaque
            ball = vtkSphereSource()
            ball.SetCenter(*[c[i] + at[i] * length for i in range(3)])
            ball.SetRadius(radius * length)
            ball.SetThetaResolution(32)
            ball.SetPhiResolution(24)
            self.ball = ball
            self.opaque = flat_actor(ball, (0.9, 0.9, 0.9), 1.0)
            self.renderer.AddActor(self.opaque)
        self.renderer.SetUseDepthPeeling(1)
        self.renderer.SetUseDepthPeelingForVolumes(1)
        self.renderer.SetMaximumNumberOfPeels(peels)
        self.renderer.SetOcclusionRatio(0.0)

    def look(self, position, focal, parallel=False, near=None):
        length = self.grid.GetLength()
        camera = self.renderer.GetActiveCamera()
        camera.SetPosition(*[p * length for p in position])
        camera.SetFocalPoint(*[p * length for p in focal])
        camera.SetViewUp(0.0, 0.0, 1.0)
        if parallel:
            camera.ParallelProjectionOn()
            camera.SetParallelScale(1.0 * length)
        self.renderer.ResetCameraClippingRange()
        if near:
            camera.SetClippingRange(near * length, 6 * length)

    def show(self, volumes, surfaces, opaque=None):
        """The volumes, the translucent surfaces of indices `surfaces`, and the opaque sphere
        (by default with the volumes)."""
        for volume in self.volumes:
            volume.SetVisibility(volumes)
        for k, (actor, _) in enumerate(self.surfaces):
            actor.SetVisibility(k in surfaces)
        if self.opaque:
            self.opaque.SetVisibility(volumes if opaque is None else opaque)

    def pixels(self):
        pixels = vtkUnsignedCharArray()
        self.window.GetPixelData(0, 0, SIZE - 1, SIZE - 1, 0, pixels, 0)
        return pixels

    def add_layers(self, reference, index):
        """Surface `index`'s fragments as the reference's layers: those facing the camera, then
        those facing away, each drawn alone and opaque and read from the depth buffer."""
        actor, opacity = self.surfaces[index]
        prop = actor.GetProperty()
        color = prop.GetAmbientColor()
        self.show(False, [index], opaque=False)
        prop.SetOpacity(1.0)
        for facing in range(2):
            prop.SetBackfaceCulling(facing == 0)
            prop.SetFrontfaceCulling(facing == 1)
            self.window.Render()
            depth = vtkFloatArray()
            self.window.GetZbufferData(0, 0, SIZE - 1, SIZE - 1, depth)
            rgba = vtkFloatArray()
            rgba.SetNumberOfComponents(4)
            rgba.SetNumberOfTuples(SIZE * SIZE)
            for i in range(SIZE * SIZE):
                hit = depth.GetValue(i) < 1.0
                rgba.SetTuple4(i, *([c * opacity for c in color] + [opacity] if hit
                                    else [0.0, 0.0, 0.0, 0.0]))
            reference.AddTranslucentLayer(rgba, depth)
            self.layers.append((rgba, depth))
        prop.SetBackfaceCulling(False)
        prop.SetFrontfaceCulling(False)
        prop.SetOpacity(opacity)

    def compare(self):
        """RMSE and max (1/255) of the window's image against the exact reference: the volumes
        and the translucent layers over what lies behind (the background and any opaque
        geometry, whose depth ends the rays)."""
        self.layers = []
        reference = vtkTetReferenceRenderer()
        self.show(False, [], opaque=True)
        self.window.Render()
        behind = self.pixels()
        if self.opaque:
            self.opaque_depth = vtkFloatArray()
            self.window.GetZbufferData(0, 0, SIZE - 1, SIZE - 1, self.opaque_depth)
            reference.SetOpaqueDepth(self.opaque_depth)
        self.add_layers(reference, 0)
        self.add_layers(reference, 1)
        self.show(True, [0, 1])
        self.window.Render()
        pixels = self.pixels()
        reference.SetCamera(self.renderer.GetActiveCamera())
        reference.SetImageSize(SIZE, SIZE)
        for volume in self.volumes:
            added = vtkTetReferenceVolume()
            added.SetInputData(self.grid)
            added.SetVolumeProperty(volume.GetProperty())
            added.SetVolume(volume)
            reference.AddVolume(added)
        if not reference.Render():
            raise RuntimeError("the reference did not render")
        # The premultiplied reference over what lies behind, rounded as a framebuffer does.
        rgba = reference.GetOutput().GetPointData().GetArray("RGBA")
        diffs = []
        for i in range(SIZE * SIZE):
            r, g, b, a = rgba.GetTuple4(i)
            for k, value in enumerate((r, g, b)):
                value += (1.0 - a) * behind.GetValue(3 * i + k) / 255.0
                exact = int(round(255.0 * min(max(value, 0.0), 1.0)))
                diffs.append(abs(pixels.GetValue(3 * i + k) - exact))
        return (sum(d * d for d in diffs) / len(diffs)) ** 0.5, max(diffs)


class TestTiledRayCastPeelingVolumes(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.grid = read_mesh("spx_vistrails.vtu")

    def check(self, name, shifts, order, position, focal, look=None, **kwargs):
        """The scene against the reference, within the bounds; its statistics."""
        scene = Scene(self.grid, shifts, order, **kwargs)
        scene.look(position, focal, **(look or {}))
        rmse, worst = scene.compare()
        stats = [v.GetMapper().GetStatistics() for v in scene.volumes]
        grouped = [s.GetNumberOfGroupedVolumes() for s in stats]
        sets = [s.GetNumberOfVolumeSetsInDepthOrder() for s in stats]
        print("%s: RMSE %.3f, max %d (grouped %s, sets in depth order %s)" % (
            name, rmse, worst, grouped, sets))
        self.assertLessEqual(rmse, RMSE_BOUND, name)
        self.assertLessEqual(worst, MAX_BOUND, name)
        for s in stats:
            self.assertTrue(s.GetDepthPeelingStage() > 0, name + ": drawn inside the peeling")
        return grouped, sets

    def test_overlapping(self):
        """Overlapping volumes: one traversal in each stage, between the stage's depths."""
        overlap = [(0, 0, 0), (0.3, 0.2, 0.1)]
        view = ((-1.5, -1.0, 0.5), (0.4, 0, 0))
        grouped, sets = self.check("two overlapping", overlap, [0, 1], *view)
        self.assertEqual(grouped, [2, 2])
        self.assertEqual(sets, [0, 0])
        self.check("two overlapping, parallel projection", overlap, [1, 0], *view,
                   look=dict(parallel=True))
        self.check("two overlapping, an opaque sphere among them", overlap, [0, 1], *view,
                   opaque=((0.2, 0.1, 0.05), 0.15))
        self.check("two overlapping, the camera inside both", overlap, [0, 1],
                   (0.15, 0.1, 0.05), (2, 0.5, 0.2), look=dict(near=0.01))
        self.check("three overlapping", [(0, 0, 0), (0.3, 0.2, 0.1), (-0.2, 0.25, -0.1)],
                   [2, 0, 1], *view)

    def test_apart(self):
        """Volumes apart, in either order of AddVolume: in depth order in each stage."""
        view = ((-2, 0.3, 0.2), (2, 0, 0))
        in_front = dict(sphere=((-0.9, 0, 0), 0.3))
        grouped, sets = self.check("apart, both behind the sphere, near added first",
                                   [(0, 0, 0), (1.5, 0, 0)], [0, 1], *view, **in_front)
        self.assertEqual(grouped, [1, 1])
        self.assertEqual(sorted(sets), [0, 2])
        self.check("apart, both behind the sphere, far added first", [(0, 0, 0), (1.5, 0, 0)],
                   [1, 0], *view, **in_front)
        self.check("apart, the sphere between", [(0, 0, 0), (1.5, 0, 0)], [1, 0], *view,
                   sphere=((0.75, 0, 0), 0.3))
        self.check("apart, parallel projection", [(0, 0, 0), (1.5, 0, 0)], [1, 0], *view,
                   look=dict(parallel=True), **in_front)
        self.check("apart, an opaque sphere between", [(0, 0, 0), (1.5, 0, 0)], [1, 0], *view,
                   opaque=((0.75, 0.1, 0), 0.2), **in_front)

    def test_group_and_apart(self):
        """A group of two and a volume apart behind it, added scrambled."""
        grouped, sets = self.check("a group of two and one apart",
                                   [(0, 0, 0), (0.3, 0.2, 0.1), (1.8, 0, 0)], [2, 0, 1],
                                   (-2, 0.3, 0.2), (3, 0, 0))
        self.assertEqual(grouped, [2, 2, 1])
        self.assertEqual(sorted(sets), [0, 0, 2])

    def test_more_than_one_traversal_takes(self):
        """Eight overlapping copies: the peeling's stages take fewer in one traversal than
        outside it (VTK's depth textures take units too); the volumes left out are drawn apart,
        over the traversal's colours in each stage's accumulation (not blended with MAX), each
        warned once, and no OpenGL error."""
        scene = Scene(self.grid, [(0.03 * i, 0.02 * i, 0.01 * i) for i in range(8)], range(8))
        scene.look((-1.5, -1.0, 0.5), (0.4, 0, 0))
        messages = []
        for volume in scene.volumes:
            mapper = volume.GetMapper()
            mapper.AddObserver("WarningEvent", lambda caller, event: messages.append("warning"))
            mapper.AddObserver("ErrorEvent", lambda caller, event: messages.append("error"))
        scene.window.Render()
        scene.window.Render()
        stats = [v.GetMapper().GetStatistics() for v in scene.volumes]
        taken = stats[0].GetNumberOfGroupedVolumes()
        print("eight overlapping in the peeling: %d in one traversal, grouped %s" % (
            taken, [s.GetNumberOfGroupedVolumes() for s in stats]))
        self.assertTrue(4 <= taken < 8)
        self.assertTrue(all(s.GetRendered() for s in stats))
        self.assertEqual(stats[0].GetNumberOfVolumeSetsInDepthOrder(), 1)
        self.assertEqual(messages, ["warning"] * (8 - taken))

    def test_remainder(self):
        """One peel where more are needed: the sets are put in order in the remainder too
        (alpha blended there, VTK's approximation: not compared)."""
        scene = Scene(self.grid, [(0, 0, 0), (0.3, 0.2, 0.1), (1.8, 0, 0)], [2, 0, 1], peels=1)
        scene.look((-2, 0.3, 0.2), (3, 0, 0))
        scene.window.Render()
        stats = [v.GetMapper().GetStatistics() for v in scene.volumes]
        self.assertEqual([s.GetDepthPeelingStage() for s in stats], [3, 3, 3])
        self.assertEqual(sorted(s.GetNumberOfVolumeSetsInDepthOrder() for s in stats), [0, 0, 2])

    def test_other_mappers(self):
        """A fragment-pipeline volume (drawn after the peeling, as alone) and VTK's projected
        tetrahedra in the same renderer: everything draws."""
        scene = Scene(self.grid, [(0, 0, 0), (1.5, 0, 0), (3.0, 0, 0)], [1, 2, 0],
                      mappers=[M, M, vtkProjectedTetrahedraMapper])
        scene.volumes[1].GetMapper().SetPipeline(M.FRAGMENT_PIPELINE)
        scene.look((-2, 0.3, 0.2), (4, 0, 0))
        warnings = []
        for volume in scene.volumes[:2]:
            volume.GetMapper().AddObserver(
                "WarningEvent", lambda caller, event: warnings.append(caller))
        scene.window.Render()
        for volume in scene.volumes[:2]:
            self.assertTrue(volume.GetMapper().GetStatistics().GetRendered())
        # Only the fragment-pipeline volume says it stands apart from the peeling; the volume
        # drawn inside it is not drawn again when that one is drawn after the peeling.
        self.assertEqual(warnings, [scene.volumes[1].GetMapper()])


if __name__ == "__main__":
    main()
