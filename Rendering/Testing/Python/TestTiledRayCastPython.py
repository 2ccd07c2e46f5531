"""vtkTiledRayCastVolumeMapper driven from Debian's /usr/bin/python3, as a pvpython script would.

Renders spx_vistrails.vtu (non-convex, several boundary layers) in a headless window, checks the
image against the exact reference renderer (RMSE <= 0.75, max <= 2 in 1/255, the bounds of the
C++ scene tests), and reads the statistics and the validation report from Python. Checks the
mapper's build progress (ProgressEvent, as any vtkAlgorithm) and that a frame without input
leaves the statistics saying nothing was rendered.
"""
import unittest

from vtkmodules.vtkCommonCore import vtkCommand, vtkFloatArray, vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkUnstructuredGrid
from vtkmodules.vtkFiltersGeneral import vtkMultiBlockDataGroupFilter
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL implementations)

from tiledraycast import vtkTetReferenceRenderer, vtkTiledRayCastVolumeMapper
from tiledraycast_testing import main, mesh_reader, offscreen_window, read_mesh, volume_property

SPX = "spx_vistrails.vtu"
SIZE = 160
# Blue to red, opacity 0.05 to 0.6, over the scalar range.
SPX_COLORS = ((0.0, (0.1, 0.3, 1.0)), (1.0, (1.0, 0.2, 0.1)))
SPX_OPACITIES = ((0.0, 0.05), (1.0, 0.6))


def spx_property(grid):
    """The ramps above, a unit distance of a tenth of the mesh's size."""
    return volume_property(grid.GetPointData().GetScalars().GetRange(), SPX_COLORS,
                           SPX_OPACITIES, 0.1 * grid.GetLength())


class TestTiledRayCastPython(unittest.TestCase):
    def test_render_matches_reference(self):
        grid = read_mesh(SPX)
        prop = spx_property(grid)
        mapper = vtkTiledRayCastVolumeMapper()
        mapper.SetInputData(grid)
        mapper.SynchronousStatisticsOn()
        volume, renderer, window = offscreen_window(mapper, prop, SIZE, multisamples=0)
        # 8-bit exact (26, 26, 38): 0.1 would be 25.5, which drivers round either way (NVIDIA
        # down, Mesa up), a 1/255 difference on every background pixel of the comparison.
        renderer.SetBackground(26 / 255.0, 26 / 255.0, 38 / 255.0)
        renderer.GetActiveCamera().Azimuth(20)
        renderer.GetActiveCamera().Elevation(30)
        renderer.GetActiveCamera().OrthogonalizeViewUp()
        renderer.ResetCameraClippingRange()
        window.Render()

        stats = mapper.GetStatistics()
        self.assertTrue(stats.GetRendered())
        self.assertGreater(stats.GetNumberOfRays(), 0)
        self.assertGreaterEqual(stats.GetNumberOfLayers(), 2)  # spx is not convex
        self.assertGreater(stats.GetMeshBytes(), 0)
        self.assertIn("rays", stats.GetSummary())
        # The pipeline setting wraps: automatic by default, which takes compute shaders where
        # the context has OpenGL 4.3 (llvmpipe and NVIDIA do).
        self.assertEqual(mapper.GetPipeline(), vtkTiledRayCastVolumeMapper.AUTOMATIC_PIPELINE)
        self.assertEqual(mapper.GetPipelineAsString(), "Automatic")
        self.assertIn(stats.GetPipeline(), ("Compute", "Fragment"))
        # Support is asked of the public class, VTK's way (vtkGPUVolumeRayCastMapper's name).
        self.assertEqual(mapper.IsRenderSupported(window, prop), 1)
        mapper.SetBlendModeToMaximumIntensity()
        self.assertEqual(mapper.IsRenderSupported(window, prop), 0)
        mapper.SetBlendModeToComposite()
        if stats.GetPipeline() == "Compute":
            self.assertGreaterEqual(stats.GetNumberOfEntries(), stats.GetNumberOfRays())
            self.assertGreater(stats.GetMeanStepsPerRay(), 1.0)
        self.assertEqual(mapper.GetValidationReport().GetNumberOfTetrahedra(),
                         grid.GetNumberOfCells())

        pixels = vtkUnsignedCharArray()
        window.GetPixelData(0, 0, SIZE - 1, SIZE - 1, 0, pixels, 0)
        depth = vtkFloatArray()
        window.GetZbufferData(0, 0, SIZE - 1, SIZE - 1, depth)
        reference = vtkTetReferenceRenderer()
        reference.SetInputData(grid)
        reference.SetVolumeProperty(prop)
        reference.SetCamera(renderer.GetActiveCamera())
        reference.SetImageSize(SIZE, SIZE)
        reference.SetVolume(volume)
        reference.SetOpaqueDepth(depth)
        reference.Render()
        image = vtkImageData()
        reference.ConvertToUnsignedChar(reference.GetOutput(), renderer.GetBackground(), image)
        exact = image.GetPointData().GetScalars()
        n = pixels.GetNumberOfValues()
        self.assertEqual(n, exact.GetNumberOfValues())
        diffs = [abs(pixels.GetValue(i) - exact.GetValue(i)) for i in range(n)]
        rmse = (sum(d * d for d in diffs) / n) ** 0.5
        print("ours vs exact reference (1/255): RMSE %.3f, max %d" % (rmse, max(diffs)))
        self.assertLessEqual(rmse, 0.75)
        self.assertLessEqual(max(diffs), 2)

    def test_composite_input_through_a_pipeline(self):
        """A multiblock from a pipeline (a reader's output port would do the same): rendered
        in one traversal, camera reset from the mapper's bounds, equal to the grid's image."""
        reader = mesh_reader(SPX)
        grid = reader.GetOutput()
        group = vtkMultiBlockDataGroupFilter()
        group.AddInputConnection(reader.GetOutputPort())
        group.AddInputData(vtkUnstructuredGrid())  # an empty block, skipped
        prop = spx_property(grid)
        images = []
        for connect in (lambda m: m.SetInputConnection(group.GetOutputPort()),
                        lambda m: m.SetInputData(grid)):
            mapper = vtkTiledRayCastVolumeMapper()
            connect(mapper)
            volume, renderer, window = offscreen_window(mapper, prop, 64, multisamples=0)
            window.Render()
            self.assertTrue(mapper.GetStatistics().GetRendered())
            pixels = vtkUnsignedCharArray()
            window.GetPixelData(0, 0, 63, 63, 0, pixels, 0)
            images.append([pixels.GetValue(i) for i in range(pixels.GetNumberOfValues())])
            if len(images) == 1:
                report = mapper.GetValidationReport()
                self.assertEqual(report.GetNumberOfBlocks(), 2)
                self.assertEqual(report.GetNumberOfEmptyBlocks(), 1)
        self.assertEqual(images[0], images[1])
        self.assertGreater(max(images[0]), 0)

    def test_progress_and_empty_frame(self):
        grid = read_mesh(SPX)
        # Opacity only: VTK's default colour and unit distance.
        prop = volume_property(grid.GetPointData().GetScalars().GetRange(), None,
                               ((0.0, 0.1), (1.0, 0.5)))
        mapper = vtkTiledRayCastVolumeMapper()
        mapper.SetInputData(grid)
        progress = []
        mapper.AddObserver(vtkCommand.ProgressEvent,
                           lambda obj, event: progress.append(obj.GetProgress()))
        volume, renderer, window = offscreen_window(mapper, prop, 64)

        # The first frame builds the mesh: progress from 0 through the build's phases to 1
        # (after the 0 and 1 of VTK's executive, which updates the mapper before its Render()).
        window.Render()
        self.assertTrue(mapper.GetStatistics().GetRendered())
        print("progress of the first frame:", ", ".join("%.3f" % p for p in progress))
        build = progress[len(progress) - 1 - progress[::-1].index(0.0):]
        self.assertEqual(build[-1], 1.0)
        self.assertEqual(build, sorted(build))
        self.assertGreaterEqual(len([p for p in build if 0.0 < p < 1.0]), 4)
        # A frame that only moves the camera rebuilds nothing, reports nothing.
        del progress[:]
        renderer.GetActiveCamera().Azimuth(30)
        window.Render()
        self.assertEqual(progress, [])
        # New scalars: a scalars-only rebuild, 0 to 1 again.
        grid.GetPointData().GetScalars().Modified()
        window.Render()
        self.assertEqual((progress[0], progress[-1]), (0.0, 1.0))

        # No input: vtkVolume never calls Render(), VTK's pipeline reports the missing input,
        # and the statistics describe that empty frame.
        errors = []
        mapper.GetExecutive().AddObserver(vtkCommand.ErrorEvent,
                                          lambda obj, event: errors.append(event))
        mapper.RemoveAllInputConnections(0)
        window.Render()
        self.assertTrue(errors)
        self.assertFalse(mapper.GetStatistics().GetRendered())
        self.assertEqual(mapper.GetStatistics().GetNumberOfRays(), 0)
        self.assertEqual(mapper.GetStatistics().GetSummary(), "nothing rendered")


if __name__ == "__main__":
    main()
