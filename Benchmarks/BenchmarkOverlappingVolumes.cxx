/*=========================================================================

  Program:   TiledRayCast
  Module:    BenchmarkOverlappingVolumes.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Overlapping volumes (docs/mapper.md, "Overlapping volumes"): the frame time of 1, 2, 4 (or any)
// copies of a mesh, each in its own vtkVolume with its own mapper, copy i shifted by
// i * 3 % (--shift 0.03) of the mesh's diagonal along x and y and given its own transfer function
// (the ramp with a unit distance growing with i), so that they overlap nearly everywhere and the
// mapper integrates them in one traversal.
//
// Usage: BenchmarkOverlappingVolumes [--size N] [--frames N] [--counts 1,2,4] [--shift f] [--csv
// file]
//          mesh.vtu...
// Each frame turns the camera by 1 degree about the focal point. Statistics are synchronous
// (each frame's GPU times read before the next), so the wall clock includes that wait.
#include "BenchmarkFrames.h"
#include "TiledRayCastSharedScenes.h"

#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTiledRayCastStatistics.h"
#include "vtkTiledRayCastVolumeMapper.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
struct Result
{
  double FirstMs = 0;
  double WallMs = 0;
  double GpuMs = 0;
  int Grouped = 0;
  vtkIdType Rays = 0;
  vtkIdType MixedRays = 0;
  double StepsPerRay = 0;
};

Result Run(vtkUnstructuredGrid* grid, int copies, int size, int frames, double shift)
{
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0, 0, 0);
  std::vector<vtkSmartPointer<vtkTiledRayCastVolumeMapper>> mappers;
  const double diagonal = grid->GetLength();
  for (int i = 0; i < copies; ++i)
  {
    auto mapper = vtkSmartPointer<vtkTiledRayCastVolumeMapper>::New();
    mapper->SetInputData(grid);
    mapper->SynchronousStatisticsOn();
    vtkNew<vtkVolume> volume;
    volume->SetMapper(mapper);
    volume->SetProperty(trcscene::MakePropertyFor(grid, 0.05 * (1 + i)));
    volume->SetPosition(shift * i * diagonal, shift * i * diagonal, 0.0);
    renderer->AddVolume(volume);
    mappers.push_back(mapper);
  }
  vtkNew<vtkRenderWindow> window;
  trcbench::SetUpWindow(window, renderer, size);

  Result result;
  vtkNew<vtkTimerLog> timer;
  result.FirstMs = trcbench::TimeFrame(window, timer);
  std::vector<double> wall, gpu;
  vtkTiledRayCastStatistics* stats = mappers.front()->GetStatistics();
  for (int f = 0; f < frames; ++f)
  {
    renderer->GetActiveCamera()->Azimuth(1);
    wall.push_back(trcbench::TimeFrame(window, timer));
    gpu.push_back(stats->GetTotalGPUTime());
  }
  result.WallMs = trcbench::Median(wall);
  result.GpuMs = trcbench::Median(gpu);
  result.Grouped = stats->GetNumberOfGroupedVolumes();
  result.Rays = stats->GetNumberOfRays();
  result.MixedRays = stats->GetNumberOfMixedRays();
  result.StepsPerRay = stats->GetMeanStepsPerRay();
  if (copies > 1 && result.Grouped != copies)
  {
    std::cerr << "warning: " << copies << " copies were not drawn in one traversal ("
              << result.Grouped << ")\n";
  }
  return result;
}
}

int main(int argc, char* argv[])
{
  trcbench::Options options;
  options.Frames = 10;
  std::vector<int> counts = { 1, 2, 4 };
  double shift = 0.03;
  for (int i = 1; i < argc; ++i)
  {
    if (trcbench::ReadOption(argc, argv, i, options))
    {
      continue;
    }
    if (!std::strcmp(argv[i], "--counts") && i + 1 < argc)
    {
      counts.clear();
      std::istringstream list(argv[++i]);
      std::string item;
      while (std::getline(list, item, ','))
      {
        counts.push_back(std::max(1, std::atoi(item.c_str())));
      }
    }
    else if (!std::strcmp(argv[i], "--shift") && i + 1 < argc)
    {
      shift = std::atof(argv[++i]);
    }
    else
    {
      options.Meshes.emplace_back(argv[i]);
    }
  }
  const int size = options.Size;
  const int frames = options.Frames;
  if (options.Meshes.empty() || counts.empty())
  {
    std::cerr << "usage: BenchmarkOverlappingVolumes [--size N] [--frames N] [--counts 1,2,4] "
                 "[--shift f] [--csv file] mesh.vtu...\n";
    return EXIT_FAILURE;
  }
  std::ofstream out;
  if (!options.Csv.empty())
  {
    out.open(options.Csv);
    out << "mesh,tets,volumes,shift,grouped,image_size,frames,first_frame_ms,wall_ms,gpu_ms,rays,"
           "mixed_rays,tets_per_ray\n";
  }
  for (const std::string& path : options.Meshes)
  {
    vtkSmartPointer<vtkUnstructuredGrid> grid = trcbench::ReadMesh(path);
    if (!grid)
    {
      continue;
    }
    const std::string mesh = trcbench::MeshName(path);
    for (int copies : counts)
    {
      const Result r = Run(grid, copies, size, frames, shift);
      std::cout << mesh << " (" << grid->GetNumberOfCells() << " tets) x" << copies << " at "
                << size << "^2: " << r.Grouped << " in one traversal, frame " << r.WallMs
                << " ms wall, " << r.GpuMs << " ms GPU (first frame " << r.FirstMs << " ms), "
                << r.Rays << " rays, " << r.MixedRays << " through a mixture, " << r.StepsPerRay
                << " tets per ray" << std::endl;
      if (out)
      {
        out << mesh << "," << grid->GetNumberOfCells() << "," << copies << "," << shift << ","
            << r.Grouped << "," << size << "," << frames << "," << r.FirstMs << "," << r.WallMs
            << "," << r.GpuMs << "," << r.Rays << "," << r.MixedRays << "," << r.StepsPerRay
            << std::endl; // kept if a later count runs out of its time limit
      }
    }
  }
  return EXIT_SUCCESS;
}
