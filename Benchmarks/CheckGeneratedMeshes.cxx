/*=========================================================================

  Program:   TiledRayCast
  Module:    CheckGeneratedMeshes.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Checks the dataset ladder's rungs made in memory (GeneratedMeshes.h) as the ladder's written
// rungs are checked: the expected counts, then what the mapper's mesh builder finds in them (no
// inverted, degenerate or overlapping tetrahedra, no crack, no duplicate point, every face shared
// by at most two tetrahedra, the boundary faces counted voxel by voxel), then the mapper's image
// against the exact reference (the tests' bounds: RMSE 0.75, max 2 / 255) at 160 x 160.
//
//   CheckGeneratedMeshes [--no-image] [--memory] [RUNG ...]   (default wavelet6_1m gym6_1m)
//
// --memory prints where the host memory goes, in bytes per tetrahedron beyond what the process
// held before (Linux /proc/self/status; the peak reset through /proc/self/clear_refs): the mesh
// builder (its scratch apart), the compact layout, then the mapper's first frame at 1024^2 (the
// same two and what the OpenGL driver keeps).
//
// The larger rungs take what their size takes (gym6_300m: 30 GB of host memory); the test of
// the build runs the 1M ones.
#include "GeneratedMeshes.h"
#include "ProcessMemory.h"
#include "TiledRayCastTestScene.h"

#include "vtkTetMesh.h"
#include "vtkTetMeshBuilder.h"
#include "vtkTetMeshCompactLayout.h"
#include "vtkTetMeshValidationReport.h"
#include "vtkTimerLog.h"

#include <iostream>
#include <string>
#include <vector>

namespace
{
using trcbench::ProcessMemory;
using trctest::Expect;

// The builder's findings on `grid` against what the rung must be.
bool CheckMesh(const generated::Rung& rung, vtkUnstructuredGrid* grid)
{
  vtkNew<vtkTetMeshBuilder> builder;
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  vtkTetMesh* mesh = builder->Build(grid);
  timer->StopTimer();
  vtkTetMeshValidationReport* report = mesh->GetReport();
  const vtkIdType boundary = generated::CountBoundaryFaces(rung.Family, rung.Voxels);
  std::cout << rung.Name << ": " << report->GetNumberOfTetrahedra() << " tetrahedra, "
            << report->GetNumberOfBoundaryFaces() << " boundary faces (expected " << boundary
            << "), built in " << timer->GetElapsedTime() << " s; " << report->GetSummary() << "\n";
  const std::string name = rung.Name;
  bool ok = Expect(report->GetUsable() && !report->HasProblems(), name + ": nothing to report");
  ok = Expect(report->GetNumberOfInvertedTetrahedra() == 0, name + ": every tet positive") && ok;
  ok = Expect(report->GetNumberOfDegenerateTetrahedra() == 0, name + ": none degenerate") && ok;
  ok = Expect(report->GetNumberOfNonManifoldFaces() == 0, name + ": manifold") && ok;
  ok = Expect(report->GetNumberOfDuplicatePoints() == 0, name + ": no duplicate point") && ok;
  return Expect(report->GetNumberOfBoundaryFaces() == boundary, name + ": boundary faces") && ok;
}

// Our default mapper showing `grid` alone at `size` x `size` pixels, the camera on its views.
struct Scene
{
  vtkNew<vtkTiledRayCastVolumeMapper> Mapper;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;

  Scene(vtkUnstructuredGrid* grid, int size)
  {
    this->Mapper->SetInputData(grid);
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(trctest::MakePropertyFor(grid, 0.05));
    this->Renderer->AddVolume(this->Volume);
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(size, size);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->ResetCamera();
    trctest::LookFrom(this->Renderer->GetActiveCamera(), 30, 20);
    this->Renderer->ResetCamera();
  }
};

// Where the host memory goes: the builder, the layout, the mapper's first frame.
void ReportMemory(const generated::Rung& rung, vtkUnstructuredGrid* grid)
{
  const double tets = static_cast<double>(grid->GetNumberOfCells());
  double base = 0.0;
  auto start = [&]()
  {
    base = ProcessMemory("VmRSS");
    trcbench::ResetPeakMemory();
  };
  auto say = [&](const char* what, double extra)
  {
    std::cout << rung.Name << " memory: " << what << ": peak "
              << (ProcessMemory("VmHWM") - base) / tets << " B/tet, then "
              << (ProcessMemory("VmRSS") - base + extra) / tets << " B/tet\n";
  };
  start();
  {
    vtkNew<vtkTetMeshBuilder> builder;
    builder->SetSpatialOrdering(true); // as the mapper does
    builder->SetPointOrdering(true);
    vtkTetMesh* mesh = builder->Build(grid);
    say("mesh builder", 0.0);
    std::cout << rung.Name << " memory: builder scratch " << builder->GetScratchMemorySize() / tets
              << " B/tet\n";
    const double built = ProcessMemory("VmRSS");
    vtkNew<vtkTetMeshCompactLayout> layout;
    layout->Build(mesh);
    std::cout << rung.Name << " memory: compact layout " << (ProcessMemory("VmRSS") - built) / tets
              << " B/tet\n";
  }
  start();
  Scene scene(grid, 1024);
  scene.Window->Render();
  say("mapper's first frame", 0.0);
  std::cout << rung.Name << ": " << scene.Mapper->GetStatistics()->GetSummary() << "\n";
}

// Our default mapper's image of `grid` against the exact reference.
bool CheckImage(const generated::Rung& rung, vtkUnstructuredGrid* grid)
{
  Scene scene(grid, 160);
  scene.Window->Render();
  return trctest::CheckAgainstReference(
    scene.Window, scene.Renderer, scene.Volume, trctest::Bounds(), rung.Name);
}
}

int main(int argc, char* argv[])
{
  bool image = true;
  bool memory = false;
  std::vector<std::string> names;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--no-image")
    {
      image = false;
    }
    else if (arg == "--memory")
    {
      memory = true;
    }
    else
    {
      names.push_back(arg);
    }
  }
  if (names.empty())
  {
    names = { "wavelet6_1m", "gym6_1m" };
  }
  bool ok = true;
  for (const std::string& name : names)
  {
    const generated::Rung* rung = generated::FindRung(name);
    if (!rung)
    {
      std::cerr << name << ": no such rung\n";
      ok = false;
      continue;
    }
    vtkSmartPointer<vtkUnstructuredGrid> grid = generated::MakeRung(*rung);
    if (!grid)
    {
      ok = false;
      continue;
    }
    if (memory)
    {
      ReportMemory(*rung, grid);
    }
    ok = CheckMesh(*rung, grid) && ok;
    ok = (!image || CheckImage(*rung, grid)) && ok;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
