/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTetGenMesherErrors.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkTetGenMesher on bad surfaces: empty input, no polygons, an open surface, a non-manifold
// edge, degenerate facets and self-intersecting surfaces (found by the -d check, and by TetGen's
// own error when the check is off). Each gives a clear error (vtkErrorMacro), an empty output
// and vtkErrorCode::UserError, never a crash or an exit; the same filter then meshes a good
// surface again.
#include "TetGenTestUtilities.h"

#include "vtkErrorCode.h"
#include "vtkTetGenMesher.h"

#include <cstdlib>

using namespace trc_tetgen_test;

namespace
{
// The surface of the tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1), outward.
vtkSmartPointer<vtkPolyData> MakeTetrahedronSurface()
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  points->InsertNextPoint(0, 0, 1);
  vtkNew<vtkCellArray> polys;
  const vtkIdType faces[4][3] = { { 1, 2, 3 }, { 0, 3, 2 }, { 0, 1, 3 }, { 0, 2, 1 } };
  for (const auto& f : faces)
  {
    polys->InsertNextCell(3, f);
  }
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->SetPoints(points);
  surface->SetPolys(polys);
  return surface;
}

// Runs the mesher on `input` and checks that it fails with a message holding `expected`.
bool FailsWith(vtkTetGenMesher* mesher, vtkPolyData* input, const std::string& expected)
{
  vtkNew<MessageRecorder> messages;
  const unsigned long tag = mesher->AddObserver(vtkCommand::ErrorEvent, messages);
  mesher->SetInputData(input);
  mesher->Update();
  mesher->RemoveObserver(tag);
  vtkUnstructuredGrid* output = mesher->GetOutput();
  const bool ok = messages->ErrorContains(expected) && output->GetNumberOfPoints() == 0 &&
    output->GetNumberOfCells() == 0 && mesher->GetErrorCode() == vtkErrorCode::UserError;
  std::cout << (ok ? "as expected: " : "UNEXPECTED: ") << "wanted \"" << expected << "\", got";
  for (const auto& e : messages->Errors)
  {
    std::cout << " [" << e.substr(e.find(':') == std::string::npos ? 0 : e.rfind("): ") + 3) << "]";
  }
  std::cout << std::endl;
  return ok;
}
}

int TestTetGenMesherErrors(int, char*[])
{
  vtkNew<vtkTetGenMesher> mesher;

  // Empty input, and points without polygons.
  vtkNew<vtkPolyData> empty;
  TRC_CHECK(FailsWith(mesher, empty, "Empty input: the surface has no points"));
  {
    vtkNew<vtkPolyData> lines;
    lines->SetPoints(MakeTetrahedronSurface()->GetPoints());
    vtkNew<vtkCellArray> cells;
    const vtkIdType line[2] = { 0, 1 };
    cells->InsertNextCell(2, line);
    lines->SetLines(cells);
    TRC_CHECK(FailsWith(mesher, lines, "no polygons or triangle strips"));
  }

  // An open surface: the box without one triangle (3 boundary edges).
  {
    auto box = MakeBox(0, 0, 0, 1, 1, 1);
    vtkNew<vtkCellArray> polys;
    auto iter = vtk::TakeSmartPointer(box->GetPolys()->NewIterator());
    for (iter->GoToFirstCell(), iter->GoToNextCell(); !iter->IsDoneWithTraversal();
         iter->GoToNextCell())
    {
      vtkIdType npts;
      const vtkIdType* pts;
      iter->GetCurrentCell(npts, pts);
      polys->InsertNextCell(npts, pts);
    }
    box->SetPolys(polys);
    TRC_CHECK(FailsWith(mesher, box, "The surface is not closed: 3 boundary edges"));
  }

  // A fin on the box: one edge shared by three triangles (plus the fin's two free edges).
  {
    auto box = MakeBox(0, 0, 0, 1, 1, 1);
    const vtkIdType tip = box->GetPoints()->InsertNextPoint(0.5, -1.0, 0.5);
    const vtkIdType fin[3] = { 0, 1, tip }; // edge 0-1 is an edge of the box
    box->GetPolys()->InsertNextCell(3, fin);
    TRC_CHECK(FailsWith(mesher, box, "1 non-manifold edges"));
  }

  // Coincident but distinct points leave the surface open (a hint names vtkCleanPolyData).
  {
    auto box = MakeBox(0, 0, 0, 1, 1, 1);
    const vtkIdType copy = box->GetPoints()->InsertNextPoint(box->GetPoint(0));
    vtkNew<vtkCellArray> polys;
    auto iter = vtk::TakeSmartPointer(box->GetPolys()->NewIterator());
    bool first = true;
    for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell())
    {
      vtkIdType npts;
      const vtkIdType* pts;
      iter->GetCurrentCell(npts, pts);
      vtkIdType ids[3] = { pts[0], pts[1], pts[2] };
      if (first && ids[0] == 0)
      {
        ids[0] = copy;
        first = false;
      }
      polys->InsertNextCell(3, ids);
    }
    box->SetPolys(polys);
    TRC_CHECK(FailsWith(mesher, box, "vtkCleanPolyData"));
  }

  // Degenerate facets: a polygon with a repeated point, and a closed surface holding a triangle
  // of three collinear points (the tetrahedron with face 0-1-2 split at the midpoint M of edge
  // 0-1 into 0-M-2 and M-1-2, plus the flat triangle 0-1-M that closes edge 0-1).
  {
    auto tet = MakeTetrahedronSurface();
    const vtkIdType repeated[3] = { 1, 1, 2 };
    tet->GetPolys()->InsertNextCell(3, repeated);
    TRC_CHECK(FailsWith(mesher, tet, "fewer than three distinct points"));
  }
  {
    auto tet = MakeTetrahedronSurface();
    const vtkIdType m = tet->GetPoints()->InsertNextPoint(0.5, 0.0, 0.0);
    vtkNew<vtkCellArray> polys;
    const vtkIdType faces[6][3] = { { 1, 2, 3 }, { 0, 3, 2 }, { 0, 1, 3 }, { 0, 2, m }, { m, 2, 1 },
      { 0, m, 1 } };
    for (const auto& f : faces)
    {
      polys->InsertNextCell(3, f);
    }
    tet->SetPolys(polys);
    TRC_CHECK(OpenEdges(tet) == 0); // closed and manifold: only the flat triangle is wrong
    TRC_CHECK(FailsWith(mesher, tet, "1 facets have no area"));
  }

  // Self-intersection: two boxes that overlap, each closed. The -d check finds it first ...
  auto overlapping = Combine(MakeBox(0, 0, 0, 1, 1, 1), MakeBox(0.5, 0.5, 0.5, 1.5, 1.5, 1.5));
  TRC_CHECK(OpenEdges(overlapping) == 0);
  TRC_CHECK(FailsWith(mesher, overlapping, "The surface intersects itself"));
  TRC_CHECK(mesher->GetNumberOfIntersectingFaces() > 0);
  TRC_CHECK(mesher->GetLastTetGenError() == 0);
  // ... and without it, TetGen's own error (it throws 3 in its library build) is caught.
  mesher->CheckSelfIntersectionsOff();
  TRC_CHECK(FailsWith(mesher, overlapping, "self-intersection"));
  TRC_CHECK(mesher->GetLastTetGenError() == 3);
  mesher->CheckSelfIntersectionsOn();

  // The same filter meshes a good surface after all that.
  auto tet = MakeTetrahedronSurface();
  mesher->SetInputData(tet);
  mesher->Update();
  TRC_CHECK(mesher->GetErrorCode() == vtkErrorCode::NoError);
  TRC_CHECK(mesher->GetLastTetGenError() == 0);
  TRC_CHECK(mesher->GetOutput()->GetNumberOfCells() == 1);
  const MeshStatistics stats = Measure(mesher->GetOutput());
  TRC_CHECK(stats.NonPositive == 0);
  TRC_CHECK(RelativeDifference(stats.Volume, 1.0 / 6.0) < 1e-15);
  return EXIT_SUCCESS;
}
