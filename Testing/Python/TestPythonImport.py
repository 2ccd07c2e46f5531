"""The 'tiledraycast' package imports next to vtkmodules and its classes work from Python."""
import sys
import unittest

from vtkmodules.vtkCommonDataModel import vtkUnstructuredGrid  # noqa: F401  (VTK first)
import tiledraycast
from tiledraycast import vtkTetMeshValidationReport


class TestPythonImport(unittest.TestCase):
    def test_report(self):
        report = vtkTetMeshValidationReport()
        self.assertTrue(report.GetUsable())
        report.SetNumberOfCrackFaces(3)
        self.assertTrue(report.HasDefects())
        self.assertIn("3 crack faces", report.GetSummary())
        report.SetError("no 3D cells")
        self.assertFalse(report.GetUsable())
        self.assertEqual(report.GetErrorMessage(), "no 3D cells")

    def test_version(self):
        self.assertRegex(tiledraycast.__version__, r"^\d+\.\d+\.\d+$")


if __name__ == "__main__":
    # ctest passes -D <data> -T <temporary>; unittest must not see them.
    unittest.main(argv=[sys.argv[0]])
