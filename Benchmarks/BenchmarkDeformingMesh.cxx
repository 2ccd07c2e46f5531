/*=========================================================================

  Program:   TiledRayCast
  Module:    BenchmarkDeformingMesh.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// A mesh whose every point moves every frame (the deformable-model use case of the source
// papers): the per-frame cost of vtkTiledRayCastVolumeMapper split into moving the points (the
// application's part), the mapper's rebuild of the GPU layout on the CPU, the rest of its CPU
// work (upload and commands), and the GPU's frame, with the wall clock of the whole frame.
//
//   wave:   z += A sin(k x + w t), slope at most 0.06: every point moves, no tet folds.
//   invert: z scaled by cos(w t) about the mesh's centre: the mesh flattens, turns inside out
//           (every tet inverted, which the builder reorients) and recovers, once a period.
//
// Usage: BenchmarkDeformingMesh [--size N] [--frames N] [--csv file] mesh.vtu...
// Statistics are synchronous (each frame's GPU times are read before the next frame), so the
// wall clock includes that wait.
#include "BenchmarkFrames.h"
#include "TiledRayCastSharedScenes.h"

#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkTiledRayCastStatistics.h"
#include "vtkTiledRayCastVolumeMapper.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace
{
// The points of frame `frame` of `mode` from the rest positions (x, y, z per point).
void Deform(const std::vector<double>& rest, const double centre[3], double size,
  const std::string& mode, int frame, int frames, vtkPoints* points)
{
  const double phase = 2.0 * 3.14159265358979 * frame / frames;
  const vtkIdType n = static_cast<vtkIdType>(rest.size() / 3);
  // The points are doubles (main() makes them so): threads write their own ranges of the buffer.
  double* out = vtkDoubleArray::SafeDownCast(points->GetData())->GetPointer(0);
  vtkSMPTools::For(0, n,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        double p[3] = { rest[3 * i], rest[3 * i + 1], rest[3 * i + 2] };
        if (mode == "wave")
        {
          // A slope of at most 0.06: no tet folds over its neighbours.
          p[2] += 0.01 * size * std::sin(6.0 * (p[0] - centre[0]) / size + phase);
        }
        else
        {
          p[2] = centre[2] + (p[2] - centre[2]) * std::cos(phase);
        }
        std::copy(p, p + 3, out + 3 * i);
      }
    });
  points->Modified();
}
}

int main(int argc, char* argv[])
{
  trcbench::Options options;
  options.MinimumFrames = 2;
  for (int i = 1; i < argc; ++i)
  {
    if (!trcbench::ReadOption(argc, argv, i, options))
    {
      options.Meshes.emplace_back(argv[i]);
    }
  }
  const int size = options.Size;
  const int frames = options.Frames;
  if (options.Meshes.empty())
  {
    std::cerr << "usage: BenchmarkDeformingMesh [--size N] [--frames N] [--csv file] mesh.vtu...\n";
    return EXIT_FAILURE;
  }
  std::ofstream out;
  if (!options.Csv.empty())
  {
    out.open(options.Csv);
    out << "mesh,tets,points,mode,image_size,frames,move_points_ms,mesh_build_ms,mapper_cpu_ms,"
           "gpu_ms,wall_ms,uploaded_mb_per_frame,first_frame_ms\n";
  }
  for (const std::string& path : options.Meshes)
  {
    vtkSmartPointer<vtkUnstructuredGrid> grid = trcbench::ReadMesh(path);
    if (!grid)
    {
      continue;
    }
    const std::string mesh = trcbench::MeshName(path);
    for (const std::string mode : { "wave", "invert" })
    {
      // Points of our own, in double, so that moving them is the application's usual work.
      vtkNew<vtkUnstructuredGrid> moving;
      moving->ShallowCopy(grid);
      vtkNew<vtkPoints> points;
      points->SetDataTypeToDouble();
      points->SetNumberOfPoints(grid->GetNumberOfPoints());
      std::vector<double> rest(3 * static_cast<size_t>(grid->GetNumberOfPoints()));
      for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
      {
        grid->GetPoint(i, &rest[3 * i]);
        points->SetPoint(i, &rest[3 * i]);
      }
      moving->SetPoints(points);
      double bounds[6], centre[3];
      grid->GetBounds(bounds);
      for (int k = 0; k < 3; ++k)
      {
        centre[k] = 0.5 * (bounds[2 * k] + bounds[2 * k + 1]);
      }
      const double extent = trcscene::Diagonal(bounds);

      vtkNew<vtkTiledRayCastVolumeMapper> mapper;
      mapper->SetInputData(moving);
      mapper->SynchronousStatisticsOn();
      vtkNew<vtkVolume> volume;
      volume->SetMapper(mapper);
      volume->SetProperty(trcscene::MakePropertyFor(moving));
      vtkNew<vtkRenderer> renderer;
      renderer->SetBackground(0, 0, 0);
      renderer->AddVolume(volume);
      vtkNew<vtkRenderWindow> window;
      trcbench::SetUpWindow(window, renderer, size);

      vtkNew<vtkTimerLog> timer;
      const double first = trcbench::TimeFrame(window, timer);
      vtkTiledRayCastStatistics* stats = mapper->GetStatistics();
      std::vector<double> move, build, cpu, gpu, wall, uploaded;
      for (int f = 1; f <= frames; ++f)
      {
        vtkNew<vtkTimerLog> frameTimer;
        frameTimer->StartTimer();
        vtkNew<vtkTimerLog> moveTimer;
        moveTimer->StartTimer();
        Deform(rest, centre, extent, mode, f, frames, points);
        moving->Modified();
        moveTimer->StopTimer();
        window->Render();
        window->WaitForCompletion();
        frameTimer->StopTimer();
        move.push_back(1000.0 * moveTimer->GetElapsedTime());
        build.push_back(1000.0 * stats->GetMeshBuildTime());
        cpu.push_back(1000.0 * stats->GetRenderTime() - 1000.0 * stats->GetMeshBuildTime());
        gpu.push_back(stats->GetTotalGPUTime()); // already in ms
        wall.push_back(1000.0 * frameTimer->GetElapsedTime());
        uploaded.push_back(stats->GetUploadedBytes() / (1024.0 * 1024.0)); // this frame's
      }
      std::cout << mesh << " " << mode << " " << size << "^2: move " << trcbench::Median(move)
                << " ms, mesh build " << trcbench::Median(build) << " ms, mapper CPU "
                << trcbench::Median(cpu) << " ms, GPU " << trcbench::Median(gpu) << " ms, wall "
                << trcbench::Median(wall) << " ms, upload " << trcbench::Median(uploaded)
                << " MB a frame (first frame " << first << " ms)\n";
      if (out)
      {
        out << mesh << "," << grid->GetNumberOfCells() << "," << grid->GetNumberOfPoints() << ","
            << mode << "," << size << "," << frames << "," << trcbench::Median(move) << ","
            << trcbench::Median(build) << "," << trcbench::Median(cpu) << ","
            << trcbench::Median(gpu) << "," << trcbench::Median(wall) << ","
            << trcbench::Median(uploaded) << "," << first << "\n";
      }
    }
  }
  return EXIT_SUCCESS;
}
