"""The 'tiledraycast' package imports next to vtkmodules, every wrapped class of its modules is
there, and its classes work from Python."""
import unittest

from vtkmodules.vtkCommonDataModel import vtkUnstructuredGrid  # noqa: F401  (VTK first)
import tiledraycast
from tiledraycast import vtkTetMeshValidationReport
from tiledraycast_testing import argument, main


def expected_classes():
    """The classes after --classes (ctest passes the modules' public classes), else none."""
    return [c for c in argument("--classes", "").split(",") if c]


class TestPythonImport(unittest.TestCase):
    def test_every_class(self):
        missing = [c for c in expected_classes() if not hasattr(tiledraycast, c)]
        self.assertEqual(missing, [], "classes that `import tiledraycast` lacks")

    def test_report(self):
        report = vtkTetMeshValidationReport()
        self.assertTrue(report.GetUsable())
        report.SetNumberOfCrackFaces(3)
        self.assertTrue(report.HasDefects())
        self.assertIn("3 crack faces", report.GetSummary())
        report.SetError("no 3D cells")
        self.assertFalse(report.GetUsable())
        self.assertEqual(report.GetErrorMessage(), "no 3D cells")

    def test_mapper_factory(self):
        # The abstract mapper's New() returns the OpenGL implementation: the wrapped module of
        # TiledRayCast::RenderingTiledRayCast registers its object factory when it is imported.
        mapper = tiledraycast.vtkTiledRayCastVolumeMapper()
        self.assertIsNotNone(mapper)
        self.assertEqual(mapper.GetClassName(), "vtkOpenGLTiledRayCastVolumeMapper")

    def test_version(self):
        self.assertRegex(tiledraycast.__version__, r"^\d+\.\d+\.\d+$")


if __name__ == "__main__":
    main()
