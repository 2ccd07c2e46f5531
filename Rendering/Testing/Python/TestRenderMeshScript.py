"""Examples/Python/render_mesh.py, the demo of `make demo`, run as a user runs it.

Runs the script (its mode and shebang are checked; it runs as an executable where the shebang's
/usr/bin/python3 is the interpreter of this test, else through this one: the GPU bundle's own
Python is not /usr/bin/python3) on a legacy .vtk
file, on a .vtu whose only array is a cell array, and on an Exodus file, all written here from
spx_vistrails.vtu; checks that each PNG exists with the asked size and that the output says which
array was used. Bad input must fail with a message: --size 0, a negative or absurd size, an
unknown extension, a missing array. The progress printer's throttling is checked on its own with
a fake clock.
"""
import io
import os
import sys
import tempfile
import unittest

from vtkmodules.vtkFiltersCore import vtkPointDataToCellData
from vtkmodules.vtkIOExodus import vtkExodusIIWriter
from vtkmodules.vtkIOLegacy import vtkUnstructuredGridWriter
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter
from tiledraycast_testing import (example_script, main, mesh_path, png_size, read_mesh,
                                  run_without_display, temporary_directory)

SCRIPT = example_script("render_mesh.py")


def run(*args):
    """Runs the script as a user does; returns (code, stdout, stderr)."""
    shebang = os.path.realpath("/usr/bin/python3") == os.path.realpath(sys.executable)
    command = [SCRIPT] if shebang else [sys.executable, SCRIPT]
    return run_without_display(command + list(args))


class TestRenderMeshScript(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.grid = read_mesh("spx_vistrails.vtu")
        cls.directory = tempfile.mkdtemp(prefix="render_mesh_", dir=temporary_directory())

    def path(self, name):
        return os.path.join(self.directory, name)

    def test_executable(self):
        self.assertTrue(os.access(SCRIPT, os.X_OK), "render_mesh.py is not executable")
        with open(SCRIPT) as script:
            self.assertEqual(script.readline().strip(), "#!/usr/bin/python3")

    def test_legacy_vtk(self):
        mesh = self.path("spx_legacy.vtk")
        writer = vtkUnstructuredGridWriter()
        writer.SetFileName(mesh)
        writer.SetInputData(self.grid)
        writer.SetFileTypeToBinary()
        self.assertEqual(writer.Write(), 1)
        output = self.path("legacy.png")
        # 256 px: the smallest size with the scalar bar and the caption.
        code, out, err = run(mesh, "--size", "256", "--output", output)
        self.assertEqual(code, 0, err)
        self.assertIn("VTK legacy data set", out)
        self.assertIn("(point data)", out)
        self.assertEqual(png_size(output), (256, 256))

    def test_cell_array(self):
        to_cells = vtkPointDataToCellData()
        to_cells.SetInputData(self.grid)
        to_cells.Update()
        cells = to_cells.GetOutput()
        cells.GetCellData().GetScalars().SetName("cellscalars")
        cells.GetPointData().Initialize()
        mesh = self.path("spx_cells.vtu")
        writer = vtkXMLUnstructuredGridWriter()
        writer.SetFileName(mesh)
        writer.SetInputData(cells)
        self.assertEqual(writer.Write(), 1)
        output = self.path("cells.png")
        code, out, err = run(mesh, "--array", "cellscalars", "--size", "80", "--output", output)
        self.assertEqual(code, 0, err)
        self.assertIn("array: cellscalars (cell data)", out)
        self.assertEqual(png_size(output), (80, 80))
        # Asking for it among the point arrays is an error that lists what there is.
        code, out, err = run(mesh, "--array", "cellscalars", "--association", "point",
                             "--output", self.path("none.png"))
        self.assertNotEqual(code, 0)
        self.assertIn("no point array 'cellscalars'", err)
        self.assertIn("cellscalars (cell)", err)

    def test_exodus(self):
        mesh = self.path("spx.exo")
        writer = vtkExodusIIWriter()
        writer.SetFileName(mesh)
        writer.SetInputData(self.grid)
        writer.WriteAllTimeStepsOff()
        self.assertEqual(writer.Write(), 1)
        output = self.path("exodus.png")
        code, out, err = run(mesh, "--size", "64", "--output", output)
        self.assertEqual(code, 0, err)
        self.assertIn("Exodus II, 1 element blocks", out)
        self.assertIn("12936 tetrahedra", out)
        self.assertEqual(png_size(output), (64, 64))
        code, out, err = run(mesh, "--time-step", "5", "--output", self.path("none.png"))
        self.assertNotEqual(code, 0)
        self.assertIn("--time-step 5 is out of range", err)

    def test_bad_input(self):
        mesh = mesh_path("spx_vistrails.vtu")
        for size in ("0", "-5", "100000", "big"):
            output = self.path("size_%s.png" % size)
            code, out, err = run(mesh, "--size", size, "--output", output)
            self.assertNotEqual(code, 0, "--size %s was accepted" % size)
            self.assertIn("--size must be", err)
            self.assertFalse(os.path.exists(output))
        unknown = self.path("mesh.xyz")
        with open(unknown, "w") as text:
            text.write("not a mesh\n")
        code, out, err = run(unknown, "--output", self.path("none.png"))
        self.assertNotEqual(code, 0)
        self.assertIn("unknown extension '.xyz'", err)
        # A .vtk that is not a legacy file: the reader's error, not "no cells".
        wrong = self.path("wrong.vtk")
        with open(wrong, "w") as text:
            text.write("<VTKFile type=\"UnstructuredGrid\">\n")
        code, out, err = run(wrong, "--output", self.path("none.png"))
        self.assertNotEqual(code, 0)
        self.assertIn("cannot be read as a VTK legacy data set file", err)
        code, out, err = run(mesh, "--array", "nosuch", "--output", self.path("none.png"))
        self.assertNotEqual(code, 0)
        self.assertIn("no array 'nosuch' (arrays: scalars (point))", err)

    def test_progress_printer(self):
        sys.path.insert(0, os.path.dirname(SCRIPT))
        try:
            import render_mesh
        finally:
            sys.path.pop(0)
        now = [0.0]
        stream = io.StringIO()
        printer = render_mesh.ProgressPrinter("building", delay=0.5, interval=0.5,
                                              stream=stream, clock=lambda: now[0])
        # Quick work prints nothing, not even its end.
        for fraction, at in ((0.0, 0.0), (0.5, 0.1), (1.0, 0.2)):
            now[0] = at
            printer.update(fraction)
        self.assertEqual(stream.getvalue(), "")
        # Slow work: a line after the delay, then at most one per interval, and 100 % at the end.
        for fraction, at in ((0.0, 1.0), (0.1, 1.2), (0.2, 1.6), (0.3, 1.7), (0.4, 2.2),
                             (1.0, 2.3)):
            now[0] = at
            printer.update(fraction)
        self.assertEqual(stream.getvalue().splitlines(),
                         ["building:  20 %", "building:  40 %", "building: 100 %"])


if __name__ == "__main__":
    main()
