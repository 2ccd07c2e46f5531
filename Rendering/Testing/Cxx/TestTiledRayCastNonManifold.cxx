/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTiledRayCastNonManifold.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Tetrahedra that overlap through a shared face (vtkTetMeshOverlapRule, docs/mesh-layout.md):
// three tetrahedra on one face (two above it, one below), in both input orders, and a block of
// tetrahedra with one cell listed twice (the first case in the fragment pipeline too). Every
// image is compared, from four views, with the exact reference (which follows the same rule
// with code of its own) and with the reference of the mesh without the tetrahedra the rule
// leaves out (an independent statement of the rule).
// Before the rule, the GPU followed one tetrahedron of the pair above the face while the
// reference composited both: the face of three up to RMSE 13.6, max 97/255 off (4 views, both
// orders), the cell listed twice up to RMSE 1.9, max 22.
#include "TiledRayCastTestGrids.h"
#include "TiledRayCastTestScene.h"

#include "vtkCellTypeSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTetMeshValidationReport.h"

#include <vector>

namespace
{
using trctest::Expect;

// The face ABC with the apexes E (above, small), F (below), G (above, large, containing the
// tetrahedron of E), cells in the order `apexes` (3 = E, 4 = F, 5 = G).
vtkSmartPointer<vtkUnstructuredGrid> FaceOfThree(const std::vector<vtkIdType>& apexes)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  points->InsertNextPoint(0.2, 0.2, 1);
  points->InsertNextPoint(0.2, 0.2, -1);
  points->InsertNextPoint(0.3, 0.3, 2);
  grid->SetPoints(points);
  for (vtkIdType apex : apexes)
  {
    const vtkIdType ids[4] = { 0, 1, 2, apex };
    grid->InsertNextCell(VTK_TETRA, 4, ids);
  }
  trctest::AddLinearScalars(grid);
  return grid;
}

// A 3x3x3 block of tetrahedra with cell `duplicate` listed again at the end; `withCopy` false
// gives the block alone.
vtkSmartPointer<vtkUnstructuredGrid> BlockWithCopy(vtkIdType duplicate, bool withCopy)
{
  vtkNew<vtkCellTypeSource> source;
  source->SetCellType(VTK_TETRA);
  source->SetBlocksDimensions(3, 3, 3);
  source->Update();
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->DeepCopy(source->GetOutput());
  if (withCopy)
  {
    vtkNew<vtkIdList> ids;
    grid->GetCellPoints(duplicate, ids);
    grid->InsertNextCell(VTK_TETRA, ids);
  }
  trctest::AddLinearScalars(grid);
  return grid;
}

// Renders `grid` from four views against the reference (its own rule) and against the
// reference of `withoutLeftOut`; checks the report's count of tetrahedra left out.
bool Check(const std::string& label, vtkUnstructuredGrid* grid, vtkUnstructuredGrid* withoutLeftOut,
  vtkIdType leftOut, int pipeline = vtkTiledRayCastVolumeMapper::AUTOMATIC_PIPELINE)
{
  double range[2];
  grid->GetPointData()->GetScalars()->GetRange(range);
  auto property = trctest::MakeProperty(range[0], range[1], 0.15 * grid->GetLength());
  trctest::WatchedVolume view(grid, property, 96);
  view.Mapper->SetPipeline(pipeline);
  bool ok = true;
  const double views[4][2] = { { 0, 80 }, { 0, -80 }, { 45, 30 }, { 200, -20 } };
  for (int v = 0; v < 4; ++v)
  {
    trctest::LookFrom(view.Renderer->GetActiveCamera(), views[v][0], views[v][1]);
    view.Renderer->ResetCamera();
    view.Renderer->GetActiveCamera()->Zoom(1.8);
    view.Window->Render();
    const std::string name = label + ", view " + std::to_string(v);
    ok = trctest::CheckAgainstReference(
           view.Window, view.Renderer, view.Volume, trctest::Bounds(), name.c_str()) &&
      ok;
    ok = trctest::CheckAgainstReference(view.Window, view.Renderer, view.Volume, trctest::Bounds(),
           (name + " (reference without the left-out)").c_str(),
           [withoutLeftOut](vtkTetReferenceRenderer* r) { r->SetInputData(withoutLeftOut); }) &&
      ok;
  }
  vtkTetMeshValidationReport* report = view.Mapper->GetValidationReport();
  ok = Expect(report->GetNumberOfOverlappingTetrahedra() == leftOut,
         label + ": " + std::to_string(leftOut) + " left out (" + report->GetSummary() + ")") &&
    ok;
  ok = Expect(view.Warnings->Text.find("overlapping tetrahedra left out") != std::string::npos,
         label + ": the warning says so") &&
    ok;
  return ok;
}
}

int TestTiledRayCastNonManifold(int, char*[])
{
  bool ok = true;
  // E first: G (which contains E's tetrahedron near the face and beyond) is left out.
  ok = Check("face of three, E first", FaceOfThree({ 3, 4, 5 }), FaceOfThree({ 3, 4 }), 1) && ok;
  // G first: E is left out.
  ok = Check("face of three, G first", FaceOfThree({ 5, 4, 3 }), FaceOfThree({ 5, 4 }), 1) && ok;
  // The fragment pipeline walks the same links.
  ok = Check("face of three, fragment pipeline", FaceOfThree({ 3, 4, 5 }), FaceOfThree({ 3, 4 }), 1,
         vtkTiledRayCastVolumeMapper::FRAGMENT_PIPELINE) &&
    ok;
  // A cell of the block's middle listed twice: the copy is left out.
  auto block = BlockWithCopy(0, false);
  const vtkIdType middle = block->GetNumberOfCells() / 2;
  ok =
    Check("cell listed twice", BlockWithCopy(middle, true), BlockWithCopy(middle, false), 1) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
