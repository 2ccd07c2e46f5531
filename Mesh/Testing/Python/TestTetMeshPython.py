"""vtkTetMeshBuilder from Python: build a mesh from a dataset, read counts, report and arrays."""
import math
import unittest

from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkTypeUInt32Array
from tiledraycast import (vtkTetMesh, vtkTetMeshBuilder, vtkTetMeshCompactLayout,
                          vtkTetMeshLayout, vtkTetMeshPaperLayout)
from tiledraycast_testing import main, read_mesh


class TestTetMeshPython(unittest.TestCase):
    def test_torus_vistrails(self):
        grid = read_mesh("torus_vistrails.vtu")
        builder = vtkTetMeshBuilder()
        mesh = builder.Build(grid)
        self.assertIsInstance(mesh, vtkTetMesh)
        self.assertEqual(builder.GetLastRebuild(), vtkTetMeshBuilder.RebuildAll)
        self.assertEqual(mesh.GetNumberOfTetrahedra(), 9216)
        self.assertEqual(mesh.GetNumberOfPoints(), 1800)
        self.assertEqual(mesh.GetNumberOfBoundaryFaces(), 1800)
        self.assertFalse(mesh.GetHasCellScalars())

        report = mesh.GetReport()
        self.assertTrue(report.GetUsable())
        self.assertEqual(report.GetNumberOfInvertedTetrahedra(), 4626)
        self.assertEqual(report.GetNumberOfDegenerateTetrahedra(), 30)
        self.assertEqual(report.GetDegenerateCellIds().GetNumberOfValues(), 30)
        self.assertIn("4626 inverted tetrahedra reoriented", report.GetSummary())

        # Per-tetrahedron queries and copies of the arrays.
        ids = [0, 0, 0, 0]
        mesh.GetTetPointIds(0, ids)
        self.assertTrue(all(0 <= i < 1800 for i in ids))
        self.assertGreater(mesh.ComputeSignedVolume(0), 0.0)
        neighbors = vtkTypeUInt32Array()
        mesh.CopyTetNeighbors(neighbors)
        self.assertEqual(neighbors.GetNumberOfTuples(), 9216)
        self.assertEqual(neighbors.GetNumberOfComponents(), 4)
        boundary = vtkTypeUInt32Array()
        mesh.CopyBoundaryFaces(boundary)
        self.assertEqual(boundary.GetNumberOfTuples(), 1800)
        # A boundary face word (t << 2) | i has no neighbour; an inner face's neighbour points
        # back at it.
        word = int(boundary.GetValue(0))
        self.assertEqual(mesh.GetNeighborTet(word >> 2, word & 3), -1)
        for face in range(4):
            n = mesh.GetNeighborTet(0, face)
            if n >= 0:
                self.assertEqual(mesh.GetNeighborTet(n, mesh.GetNeighborFace(0, face)), 0)
        scalars = vtkDoubleArray()
        mesh.CopyScalars(scalars)
        self.assertEqual(scalars.GetNumberOfTuples(), 1800)
        gradient = [0.0] * 4
        self.assertTrue(mesh.ComputeScalarGradient(0, gradient))
        normals = [0.0] * 12
        mesh.ComputeFaceNormals(0, normals, True)
        self.assertAlmostEqual(math.sqrt(sum(x * x for x in normals[0:3])), 1.0, places=12)

        # Nothing changed: nothing rebuilt.
        builder.Build(grid)
        self.assertEqual(builder.GetLastRebuild(), vtkTetMeshBuilder.RebuildNothing)

        # The two layouts and their byte counts.
        paper = vtkTetMeshPaperLayout()
        paper.SetTextureWidth(1024)  # 9216 = 9 x 1024: no padding
        self.assertTrue(paper.Build(mesh))
        self.assertEqual(paper.GetBytesPerTet(), 144.0)
        self.assertEqual(paper.GetArrayKind(0), vtkTetMeshLayout.Texture2D)
        size = [0, 0]
        paper.GetArrayTextureSize(0, size)
        self.assertEqual(size, [1024, 27])
        compact = vtkTetMeshCompactLayout()
        self.assertTrue(compact.Build(mesh))
        self.assertAlmostEqual(compact.GetBytesPerTet(), 32.0 + 16.0 * 1800 / 9216, places=12)
        self.assertEqual(compact.GetArrayName(0), "TetPoints")

    def test_unusable(self):
        from vtkmodules.vtkCommonDataModel import vtkUnstructuredGrid
        from vtkmodules.vtkCommonCore import vtkCommand
        builder = vtkTetMeshBuilder()
        errors = []
        builder.AddObserver(vtkCommand.ErrorEvent, lambda obj, event: errors.append(event))
        mesh = builder.Build(vtkUnstructuredGrid())
        self.assertFalse(mesh.GetReport().GetUsable())
        self.assertIn("empty", mesh.GetReport().GetErrorMessage())
        self.assertEqual(len(errors), 1)


if __name__ == "__main__":
    main()
