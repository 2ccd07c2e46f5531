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
// Usage: BenchmarkDeformingMesh [--size N] [--frames N] [--csv file] [--point-update cpu|gpu|both]
//        mesh.vtu...
// Each motion is played with the mapper's PointUpdate on the CPU (the CPU rebuilds the points)
// and on the GPU (the input's coordinates go straight to the GPU), interleaved in one run
// (--point-update picks one). Statistics are synchronous in the timed frames (each frame's GPU
// times are read before the next frame), so their wall clock includes that wait; the same frames
// are then played again without them, back to back, and timed as a whole (frame_ms_free: what an
// application that renders frames one after the other gets; frame_ms_free_median: the median of
// the intervals between one frame's Render() returning and the next's, the typical frame).
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

// One motion of `grid`, `frames` frames timed with synchronous statistics, then the same frames
// again without them, timed as a whole; a line on stdout and in the CSV.
void Play(vtkUnstructuredGrid* grid, const std::string& mesh, const std::string& mode, bool onGPU,
  int size, int frames, std::ofstream& out)
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
  mapper->SetPointUpdate(onGPU ? vtkTiledRayCastVolumeMapper::GPU_POINT_UPDATE
                               : vtkTiledRayCastVolumeMapper::CPU_POINT_UPDATE);
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
  int alone = 0, rebuilt = 0;
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
    const int rebuild = stats->GetMeshRebuild();
    alone += rebuild == vtkTiledRayCastStatistics::MeshRebuildPointsOnGPU ? 1 : 0;
    rebuilt += (rebuild & vtkTiledRayCastStatistics::MeshRebuildPoints) ? 1 : 0;
  }
  // The same frames without waiting for each one's GPU times.
  mapper->SynchronousStatisticsOff();
  window->WaitForCompletion();
  vtkNew<vtkTimerLog> freeTimer;
  freeTimer->StartTimer();
  std::vector<double> freeFrames; // from one Render() returning to the next
  double last = freeTimer->GetUniversalTime();
  for (int f = 1; f <= frames; ++f)
  {
    Deform(rest, centre, extent, mode, f, frames, points);
    moving->Modified();
    window->Render();
    const double now = freeTimer->GetUniversalTime();
    freeFrames.push_back(1000.0 * (now - last));
    last = now;
  }
  window->WaitForCompletion();
  freeTimer->StopTimer();
  const double free = 1000.0 * freeTimer->GetElapsedTime() / frames;
  // The typical frame back to back: the median of the frames' intervals, which leaves out the
  // frames the CPU rebuilds in full (the invert motion's two where the mesh turns inside out)
  // that the mean above holds.
  const double freeMedian = trcbench::Median(freeFrames);
  std::cout << mesh << " " << mode << (onGPU ? ", points on the GPU" : ", points on the CPU") << " "
            << size << "^2: move " << trcbench::Median(move) << " ms, mesh build "
            << trcbench::Median(build) << " ms, mapper CPU " << trcbench::Median(cpu) << " ms, GPU "
            << trcbench::Median(gpu) << " ms, wall " << trcbench::Median(wall) << " ms, upload "
            << trcbench::Median(uploaded) << " MB a frame (first frame " << first << " ms); "
            << alone << " frames moved on the GPU alone, " << rebuilt
            << " rebuilt on the CPU; frames back to back " << free << " ms each (median "
            << freeMedian << ")\n";
  if (out)
  {
    out << mesh << "," << grid->GetNumberOfCells() << "," << grid->GetNumberOfPoints() << ","
        << mode << "," << (onGPU ? "gpu" : "cpu") << "," << size << "," << frames << ","
        << trcbench::Median(move) << "," << trcbench::Median(build) << "," << trcbench::Median(cpu)
        << "," << trcbench::Median(gpu) << "," << trcbench::Median(wall) << ","
        << trcbench::Median(uploaded) << "," << first << "," << alone << "," << rebuilt << ","
        << free << "," << freeMedian << "\n";
  }
}
}

int main(int argc, char* argv[])
{
  struct : trcbench::Options
  {
    std::vector<bool> PointsOnGPU{ false, true };
  } options;
  options.MinimumFrames = 2;
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--point-update") && i + 1 < argc)
    {
      const std::string which = argv[++i];
      options.PointsOnGPU = which == "gpu" ? std::vector<bool>{ true }
        : which == "cpu"                   ? std::vector<bool>{ false }
        : which == "both"                  ? std::vector<bool>{ false, true }
                                           : std::vector<bool>{};
    }
    else if (!trcbench::ReadOption(argc, argv, i, options))
    {
      options.Meshes.emplace_back(argv[i]);
    }
  }
  const int size = options.Size;
  const int frames = options.Frames;
  if (options.Meshes.empty() || options.PointsOnGPU.empty())
  {
    std::cerr << "usage: BenchmarkDeformingMesh [--size N] [--frames N] [--csv file] "
                 "[--point-update cpu|gpu|both] mesh.vtu...\n";
    return EXIT_FAILURE;
  }
  std::ofstream out;
  if (!options.Csv.empty())
  {
    out.open(options.Csv);
    out << "mesh,tets,points,mode,point_update,image_size,frames,move_points_ms,mesh_build_ms,"
           "mapper_cpu_ms,gpu_ms,wall_ms,uploaded_mb_per_frame,first_frame_ms,frames_on_gpu_alone,"
           "frames_rebuilt_on_cpu,frame_ms_free,frame_ms_free_median\n";
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
      for (const bool onGPU : options.PointsOnGPU)
      {
        Play(grid, mesh, mode, onGPU, size, frames, out);
      }
    }
  }
  return EXIT_SUCCESS;
}
