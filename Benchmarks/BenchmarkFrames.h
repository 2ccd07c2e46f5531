/*=========================================================================

  Program:   TiledRayCast
  Module:    BenchmarkFrames.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// What the frame-timing benchmarks of one mapper (BenchmarkDeformingMesh,
// BenchmarkOverlappingVolumes; BenchmarkMappers takes its median) share, so that their figures come from the same scene and clock:
// the options every one takes, reading a mesh, the window and camera, the timed first frame and
// the median of the frames.
#ifndef BenchmarkFrames_h
#define BenchmarkFrames_h

#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

namespace trcbench
{
// The median, `none` (0 where not given) for none.
inline double Median(std::vector<double> values, double none = 0.0)
{
  if (values.empty())
  {
    return none;
  }
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// The options of every frame benchmark: --size N (square image), --frames N (at least
// MinimumFrames), --csv file, and the meshes.
struct Options
{
  int Size = 1024;
  int Frames = 20;
  int MinimumFrames = 1;
  std::string Csv;
  std::vector<std::string> Meshes;
};

// Reads argv[i] (and its value, advancing i) when it is --size, --frames or --csv; false for
// anything else, which the program reads itself (its own options, then meshes).
inline bool ReadOption(int argc, char* argv[], int& i, Options& options)
{
  if (!std::strcmp(argv[i], "--size") && i + 1 < argc)
  {
    options.Size = std::atoi(argv[++i]);
  }
  else if (!std::strcmp(argv[i], "--frames") && i + 1 < argc)
  {
    options.Frames = std::max(options.MinimumFrames, std::atoi(argv[++i]));
  }
  else if (!std::strcmp(argv[i], "--csv") && i + 1 < argc)
  {
    options.Csv = argv[++i];
  }
  else
  {
    return false;
  }
  return true;
}

// The mesh at `path`, or null (said on stderr) when it has no cells or no point scalars.
inline vtkSmartPointer<vtkUnstructuredGrid> ReadMesh(const std::string& path)
{
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkSmartPointer<vtkUnstructuredGrid> grid = reader->GetOutput();
  if (grid->GetNumberOfCells() == 0 || !grid->GetPointData()->GetScalars())
  {
    std::cerr << path << ": no cells or no point scalars; skipped\n";
    return nullptr;
  }
  return grid;
}

// The file name of `path`, for the printed lines and the CSV.
inline std::string MeshName(const std::string& path)
{
  return path.substr(path.find_last_of('/') + 1);
}

// An off-screen square window of `size` pixels without multisampling, showing `renderer` from
// the benchmarks' view: the whole scene, turned 30 degrees in azimuth and 20 in elevation.
inline void SetUpWindow(vtkRenderWindow* window, vtkRenderer* renderer, int size)
{
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(size, size);
  window->AddRenderer(renderer);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Azimuth(30);
  renderer->GetActiveCamera()->Elevation(20);
  renderer->ResetCameraClippingRange();
}

// Milliseconds of one frame until the GPU has finished it (timed with `timer`).
inline double TimeFrame(vtkRenderWindow* window, vtkTimerLog* timer)
{
  timer->StartTimer();
  window->Render();
  window->WaitForCompletion();
  timer->StopTimer();
  return 1000.0 * timer->GetElapsedTime();
}
}

#endif
