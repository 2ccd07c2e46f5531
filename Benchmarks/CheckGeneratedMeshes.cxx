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
#include "TiledRayCastTestScene.h"

#include "vtkTetMesh.h"
#include "vtkTetMeshBuilder.h"
#include "vtkTetMeshCompactLayout.h"
#include "vtkTetMeshValidationReport.h"
#include "vtkTimerLog.h"

#include <cstring>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace
{
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

// A field of /proc/self/status in bytes (VmRSS, VmHWM).
double ProcessMemory(const char* field)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  const size_t length = std::strlen(field);
  while (std::getline(status, line))
  {
    if (line.compare(0, length, field) == 0 && line.size() > length && line[length] == ':')
    {
      return 1024.0 * std::atof(line.c_str() + length + 1);
    }
  }
  return 0.0;
}

// Where the host memory goes: the builder, the layout, the mapper's first frame.
void ReportMemory(const generated::Rung& rung, vtkUnstructuredGrid* grid)
{
  const double tets = static_cast<double>(grid->GetNumberOfCells());
  double base = 0.0;
  auto start = [&]()
  {
    base = ProcessMemory("VmRSS");
    std::ofstream("/proc/self/clear_refs") << "5";
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
  vtkNew<vtkTiledRayCastVolumeMapper> mapper;
  mapper->SetInputData(grid);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(trctest::MakePropertyFor(grid, 0.05));
  vtkNew<vtkRenderer> renderer;
  renderer->AddVolume(volume);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(1024, 1024);
  window->AddRenderer(renderer);
  window->Render();
  say("mapper's first frame", 0.0);
  std::cout << rung.Name << ": " << mapper->GetStatistics()->GetSummary() << "\n";
}

// Our default mapper's image of `grid` against the exact reference.
bool CheckImage(const generated::Rung& rung, vtkUnstructuredGrid* grid)
{
  vtkNew<vtkTiledRayCastVolumeMapper> mapper;
  mapper->SetInputData(grid);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(trctest::MakePropertyFor(grid, 0.05));
  vtkNew<vtkRenderer> renderer;
  renderer->AddVolume(volume);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(160, 160);
  window->AddRenderer(renderer);
  renderer->ResetCamera();
  trctest::LookFrom(renderer->GetActiveCamera(), 30, 20);
  renderer->ResetCamera();
  window->Render();
  return trctest::CheckAgainstReference(window, renderer, volume, trctest::Bounds(), rung.Name);
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
