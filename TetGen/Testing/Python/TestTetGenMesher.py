"""vtkTetGenMesher from Python: it is imported by name (never by `import tiledraycast`, which must
not load AGPL-3+ TetGen), it meshes a sphere into positive tetrahedra that fill the polyhedron,
and a bad surface gives an error event and an empty output. Skipped (125) when the optional
module TiledRayCast::FiltersTetGen was not built."""
import subprocess
import sys
import unittest

from vtkmodules.util.misc import calldata_type
from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand, vtkIdList
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData, vtkTetra
from vtkmodules.vtkFiltersCore import vtkMassProperties
from vtkmodules.vtkFiltersSources import vtkSphereSource
from tiledraycast_testing import main

try:
    from tiledraycast.vtkFiltersTetGen import vtkTetGenMesher
except ImportError:
    sys.exit(125)


def sphere_surface():
    source = vtkSphereSource()
    source.SetThetaResolution(32)
    source.SetPhiResolution(16)
    source.Update()
    surface = vtkPolyData()
    surface.ShallowCopy(source.GetOutput())
    return surface


class TestTetGenMesher(unittest.TestCase):
    def test_import_tiledraycast_does_not_load_tetgen(self):
        # A fresh interpreter: import the package and look for libtet among its mappings.
        code = (
            "import tiledraycast, sys\n"
            "maps = open('/proc/self/maps').read()\n"
            "sys.exit(1 if 'libtet' in maps or 'vtkFiltersTetGen' in maps else 0)\n"
        )
        self.assertEqual(subprocess.call([sys.executable, "-c", code]), 0)

    def test_sphere(self):
        surface = sphere_surface()
        mesher = vtkTetGenMesher()
        mesher.SetInputData(surface)
        mesher.QualityOn()
        mesher.SetRadiusEdgeRatio(1.414)
        mesher.SetMaximumVolume(0.001)
        progress = []
        mesher.AddObserver(vtkCommand.ProgressEvent,
                           lambda obj, event: progress.append(obj.GetProgress()))
        mesher.Update()
        self.assertEqual(mesher.GetTetGenSwitches(), "pq1.414a0.001zJQ")
        mesh = mesher.GetOutput()
        self.assertGreater(mesh.GetNumberOfCells(), 500)
        self.assertEqual(progress[-1], 1.0)

        points = mesh.GetPoints()
        total = 0.0
        for c in range(mesh.GetNumberOfCells()):
            ids = mesh.GetCell(c).GetPointIds()
            volume = vtkTetra.ComputeVolume(*[points.GetPoint(ids.GetId(k)) for k in range(4)])
            self.assertGreater(volume, 0.0)
            total += volume
        # vtkMassProperties measures the polyhedron. The sphere's float points make TetGen's
        # added surface points round to float as well, hence 1e-6 rather than rounding level.
        mass = vtkMassProperties()
        mass.SetInputData(surface)
        mass.Update()
        self.assertAlmostEqual(total / mass.GetVolume(), 1.0, delta=1e-6)

    def test_open_surface(self):
        # The sphere without its last triangle.
        sphere = sphere_surface()
        polys = vtkCellArray()
        ids = vtkIdList()
        for c in range(sphere.GetNumberOfPolys() - 1):
            sphere.GetPolys().GetCellAtId(c, ids)
            polys.InsertNextCell(ids)
        surface = vtkPolyData()
        surface.SetPoints(sphere.GetPoints())
        surface.SetPolys(polys)

        messages = []

        @calldata_type(VTK_STRING)
        def on_error(obj, event, message):
            messages.append(message)

        mesher = vtkTetGenMesher()
        mesher.AddObserver(vtkCommand.ErrorEvent, on_error)
        mesher.SetInputData(surface)
        mesher.Update()
        self.assertEqual(mesher.GetOutput().GetNumberOfCells(), 0)
        self.assertEqual(mesher.GetOutput().GetNumberOfPoints(), 0)
        self.assertNotEqual(mesher.GetErrorCode(), 0)
        self.assertEqual(len(messages), 1)
        self.assertIn("The surface is not closed: 3 boundary edges", messages[0])


if __name__ == "__main__":
    main()
