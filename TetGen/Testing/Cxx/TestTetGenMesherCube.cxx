/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTetGenMesherCube.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkTetGenMesher on a box: the tetrahedra fill exactly the enclosed volume, all positively
// oriented, and their boundary is the box; with PreserveSurface the boundary triangles are the
// input's own; polygons can reach TetGen as facets; progress is reported by phase.
#include "TetGenTestUtilities.h"

#include "vtkIdTypeArray.h"
#include "vtkPointData.h"
#include "vtkTetGenMesher.h"

#include <cstdlib>
#include <sstream>

using namespace trc_tetgen_test;

namespace
{
// Tolerances. The box's volume (6) and area (22) are exact in double precision; summing a few
// thousand tetrahedra or triangles costs a few ulps each, far below 1e-12 relative. A missing or
// overlapping tetrahedron would be off by at least its volume, which is above 1e-6 here.
constexpr double VolumeTolerance = 1e-12;
constexpr double AreaTolerance = 1e-12;

class ProgressRecorder : public vtkCommand
{
public:
  static ProgressRecorder* New() { return new ProgressRecorder; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    this->Values.push_back(*static_cast<double*>(data));
  }
  std::vector<double> Values;
};
}

int TestTetGenMesherCube(int, char*[])
{
  auto box = MakeBox(-1.0, 0.0, 0.0, 2.0, 1.0, 2.0); // 3 x 1 x 2
  const double volume = 6.0;
  const double area = 22.0;
  TRC_CHECK(RelativeDifference(EnclosedVolume(box), volume) < VolumeTolerance);

  // Plain -p: the constrained Delaunay tetrahedralization of the box, few tetrahedra.
  vtkNew<vtkTetGenMesher> mesher;
  vtkNew<ProgressRecorder> progress;
  mesher->AddObserver(vtkCommand::ProgressEvent, progress);
  mesher->SetInputData(box);
  mesher->Update();
  vtkUnstructuredGrid* mesh = mesher->GetOutput();
  TRC_CHECK(std::string(mesher->GetTetGenSwitches()) == "pzJQ");
  TRC_CHECK(mesher->GetErrorCode() == 0);
  TRC_CHECK(mesh->GetNumberOfCells() > 0);
  MeshStatistics stats = Measure(mesh);
  TRC_CHECK(stats.NonTetrahedra == 0);
  TRC_CHECK(stats.NonPositive == 0);
  TRC_CHECK(RelativeDifference(stats.Volume, volume) < VolumeTolerance);
  auto boundary = Boundary(mesh);
  TRC_CHECK(RelativeDifference(SurfaceArea(boundary), area) < AreaTolerance);
  TRC_CHECK(OpenEdges(boundary) == 0);
  TRC_CHECK(EulerCharacteristic(boundary) == 2);
  const vtkIdType plainCount = mesh->GetNumberOfCells();

  // Progress: the observable phases, in order, ending at 1.
  TRC_CHECK(progress->Values.size() >= 5);
  TRC_CHECK(std::is_sorted(progress->Values.begin(), progress->Values.end()));
  TRC_CHECK(
    std::find(progress->Values.begin(), progress->Values.end(), 0.85) != progress->Values.end());
  TRC_CHECK(progress->Values.back() == 1.0);

  // Quality and a volume bound: many more tetrahedra, none above the bound (TetGen can miss it
  // next to the surface, see TestTetGenMesherTorus; not on this box).
  mesher->QualityOn();
  mesher->SetRadiusEdgeRatio(1.414);
  mesher->SetMaximumVolume(0.01);
  mesher->Update();
  mesh = mesher->GetOutput();
  TRC_CHECK(std::string(mesher->GetTetGenSwitches()) == "pq1.414a0.01zJQ");
  stats = Measure(mesh);
  TRC_CHECK(stats.NonTetrahedra == 0);
  TRC_CHECK(stats.NonPositive == 0);
  TRC_CHECK(RelativeDifference(stats.Volume, volume) < VolumeTolerance);
  TRC_CHECK(stats.MaximumVolume <= 0.01);
  TRC_CHECK(mesh->GetNumberOfCells() >= 600); // volume / bound
  TRC_CHECK(mesh->GetNumberOfCells() > plainCount);
  boundary = Boundary(mesh);
  TRC_CHECK(RelativeDifference(SurfaceArea(boundary), area) < AreaTolerance);
  TRC_CHECK(EulerCharacteristic(boundary) == 2);
  TRC_CHECK(boundary->GetNumberOfPolys() > 12); // TetGen split the surface

  // The surface kept (-Y): the boundary is exactly the 12 input triangles over the 8 input
  // points, which come first in the output. (TetGen then adds no point at all in so simple a
  // box: every interior point it tries would encroach upon the surface it may not split.)
  mesher->PreserveSurfaceOn();
  mesher->Update();
  mesh = mesher->GetOutput();
  TRC_CHECK(std::string(mesher->GetTetGenSwitches()) == "pq1.414a0.01YzJQ");
  stats = Measure(mesh);
  TRC_CHECK(stats.NonTetrahedra == 0);
  TRC_CHECK(stats.NonPositive == 0);
  TRC_CHECK(RelativeDifference(stats.Volume, volume) < VolumeTolerance);
  for (vtkIdType i = 0; i < box->GetNumberOfPoints(); ++i)
  {
    double in[3], out[3];
    box->GetPoint(i, in);
    mesh->GetPoint(i, out);
    TRC_CHECK(in[0] == out[0] && in[1] == out[1] && in[2] == out[2]);
  }
  boundary = Boundary(mesh);
  TRC_CHECK(boundary->GetNumberOfPolys() == 12);
  TRC_CHECK(RelativeDifference(SurfaceArea(boundary), area) < AreaTolerance);
  {
    auto meshIds =
      vtkIdTypeArray::SafeDownCast(boundary->GetPointData()->GetArray("vtkOriginalPointIds"));
    TRC_CHECK(meshIds);
    std::set<std::array<vtkIdType, 3>> expected, found;
    auto collect =
      [](vtkPolyData* surface, vtkIdTypeArray* map, std::set<std::array<vtkIdType, 3>>& triangles)
    {
      auto iter = vtk::TakeSmartPointer(surface->GetPolys()->NewIterator());
      for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell())
      {
        vtkIdType npts;
        const vtkIdType* pts;
        iter->GetCurrentCell(npts, pts);
        std::array<vtkIdType, 3> t = { pts[0], pts[1], pts[2] };
        for (auto& id : t)
        {
          id = map ? map->GetValue(id) : id;
        }
        std::sort(t.begin(), t.end());
        triangles.insert(t);
      }
    };
    collect(box, nullptr, expected);
    collect(boundary, meshIds, found);
    TRC_CHECK(expected == found);
  }

  // Quads as TetGen facets: the same volume and boundary.
  auto quadBox = MakeBox(-1.0, 0.0, 0.0, 2.0, 1.0, 2.0, true);
  vtkNew<vtkTetGenMesher> facets;
  facets->SetInputData(quadBox);
  facets->PolygonsAsFacetsOn();
  facets->QualityOn();
  facets->Update();
  stats = Measure(facets->GetOutput());
  TRC_CHECK(facets->GetOutput()->GetNumberOfCells() > 0);
  TRC_CHECK(stats.NonPositive == 0);
  TRC_CHECK(RelativeDifference(stats.Volume, volume) < VolumeTolerance);
  boundary = Boundary(facets->GetOutput());
  TRC_CHECK(RelativeDifference(SurfaceArea(boundary), area) < AreaTolerance);
  TRC_CHECK(EulerCharacteristic(boundary) == 2);

  // The same quads triangulated by VTK first (the default) mesh just as well.
  facets->PolygonsAsFacetsOff();
  facets->Update();
  TRC_CHECK(RelativeDifference(Measure(facets->GetOutput()).Volume, volume) < VolumeTolerance);

  std::ostringstream printed;
  mesher->Print(printed);
  TRC_CHECK(printed.str().find("TetGenSwitches: pq1.414a0.01YzJQ") != std::string::npos);
  return EXIT_SUCCESS;
}
