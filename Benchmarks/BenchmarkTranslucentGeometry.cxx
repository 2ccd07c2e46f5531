/*=========================================================================

  Program:   TiledRayCast
  Module:    BenchmarkTranslucentGeometry.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Translucent geometry in depth order (docs/mapper.md, "Translucent geometry"): the frame time
// of a mesh with the translucent sphere and plane of TestTiledRayCastTranslucent
// (TiledRayCastTranslucentScene.h), side by side in one run:
//   volume                   the volume alone
//   geometry                 the translucent geometry alone, VTK's dual depth peeling
//   volume+geometry          both, the geometry depth peeled and the volume drawn after it
//                            (depth peeling for volumes off: VTK's order, the wrong image)
//   volume+geometry peeled   both, depth peeling for volumes on: the mapper takes part in
//                            every stage of the peeling (the right image)
//
// Usage: BenchmarkTranslucentGeometry [--size N] [--frames N] [--peels N] [--csv file] mesh.vtu...
// Each frame turns the camera by 1 degree about the focal point; the wall clock runs until the
// GPU has finished the frame (statistics asynchronous, as in an application).
#include "BenchmarkFrames.h"
#include "TiledRayCastSharedScenes.h"
#include "TiledRayCastTranslucentScene.h"

#include "vtkTiledRayCastStatistics.h"
#include "vtkTiledRayCastVolumeMapper.h"
#include "vtkVolume.h"

#include <fstream>

namespace
{
struct Result
{
  double FirstMs = 0;
  double WallMs = 0;
  int Draws = 0; // of the volume per frame (1 without depth peeling for volumes)
};

Result Run(vtkUnstructuredGrid* grid, int scene, const trcbench::Options& options, int peels)
{
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0, 0, 0);
  vtkNew<vtkTiledRayCastVolumeMapper> mapper;
  mapper->SetInputData(grid);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(trcscene::MakePropertyFor(grid, 0.05));
  renderer->AddVolume(volume);
  trcscene::TranslucentGeometry translucent(grid, renderer, peels);
  volume->SetVisibility(scene != 1);
  translucent.Show(scene != 0, scene != 0);
  renderer->SetUseDepthPeelingForVolumes(scene == 3);
  vtkNew<vtkRenderWindow> window;
  window->SetAlphaBitPlanes(1);
  trcbench::SetUpWindow(window, renderer, options.Size);

  Result result;
  vtkNew<vtkTimerLog> timer;
  result.FirstMs = trcbench::TimeFrame(window, timer);
  std::vector<double> wall;
  for (int f = 0; f < options.Frames; ++f)
  {
    renderer->GetActiveCamera()->Azimuth(1);
    wall.push_back(trcbench::TimeFrame(window, timer));
  }
  result.WallMs = trcbench::Median(wall);
  vtkTiledRayCastStatistics* stats = mapper->GetStatistics();
  result.Draws = scene == 1 ? 0 : std::max(1, stats->GetNumberOfDepthPeelingDraws());
  return result;
}
}

int main(int argc, char* argv[])
{
  trcbench::Options options;
  options.Frames = 10;
  int peels = 8;
  for (int i = 1; i < argc; ++i)
  {
    if (trcbench::ReadOption(argc, argv, i, options))
    {
      continue;
    }
    if (!std::strcmp(argv[i], "--peels") && i + 1 < argc)
    {
      peels = std::max(1, std::atoi(argv[++i]));
    }
    else
    {
      options.Meshes.emplace_back(argv[i]);
    }
  }
  if (options.Meshes.empty())
  {
    std::cerr << "usage: BenchmarkTranslucentGeometry [--size N] [--frames N] [--peels N] "
                 "[--csv file] mesh.vtu...\n";
    return EXIT_FAILURE;
  }
  std::ofstream out;
  if (!options.Csv.empty())
  {
    out.open(options.Csv);
    out << "mesh,tets,scene,image_size,frames,peels,volume_draws_per_frame,first_frame_ms,"
           "wall_ms\n";
  }
  const char* scenes[4] = { "volume", "geometry", "volume+geometry", "volume+geometry peeled" };
  for (const std::string& path : options.Meshes)
  {
    vtkSmartPointer<vtkUnstructuredGrid> grid = trcbench::ReadMesh(path);
    if (!grid)
    {
      continue;
    }
    const std::string mesh = trcbench::MeshName(path);
    for (int scene = 0; scene < 4; ++scene)
    {
      const Result r = Run(grid, scene, options, peels);
      std::cout << mesh << " (" << grid->GetNumberOfCells() << " tets), " << scenes[scene] << " at "
                << options.Size << "^2: frame " << r.WallMs << " ms (first " << r.FirstMs
                << " ms), " << r.Draws << " volume draws per frame\n";
      if (out)
      {
        out << mesh << "," << grid->GetNumberOfCells() << "," << scenes[scene] << ","
            << options.Size << "," << options.Frames << "," << peels << "," << r.Draws << ","
            << r.FirstMs << "," << r.WallMs << "\n";
      }
    }
  }
  return EXIT_SUCCESS;
}
