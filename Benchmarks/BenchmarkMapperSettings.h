/*=========================================================================

  Program:   TiledRayCast
  Module:    BenchmarkMapperSettings.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// BenchmarkMappers' options, and the settings it times: ours in the sweep the options choose,
// then VTK's mappers. See BenchmarkMappers.cxx for the options and docs/benchmarks.md for the
// protocol.
#ifndef BenchmarkMapperSettings_h
#define BenchmarkMapperSettings_h

#include "vtkAbstractVolumeMapper.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <functional>
#include <string>
#include <vector>

class vtkUnstructuredGrid;

namespace trcmappers
{
// The command line of BenchmarkMappers (its header says what each option does).
struct Options
{
  std::vector<int> Sizes;
  int Frames = 12;
  std::string Csv;
  bool OursOnly = false;
  bool Others = true;
  bool ProjectedTetrahedraOnly = false;
  std::string Sweep = "quick"; // quick, full, defaults, pipelines, default or buffers
  vtkIdType ZSweepMaxTets = 300000;
  std::vector<int> Resample = { 64, 128, 256 };
  bool Reference = true;
  std::string Order = "input";
  std::string TransferFunction = "ramp";
  double Rate = 0;
  bool Shade = false;
  std::vector<std::string> Meshes;
};

// A setting: a name, a mapper family, and how to make its mapper (and, for resampling, the
// time it took).
struct Setting
{
  std::string Mapper, Name;
  std::function<vtkSmartPointer<vtkAbstractVolumeMapper>(double& prepareMs)> Make;
  double Rate = 0; // the window's desired update rate while timed (0: VTK's still rate)
};

// Every setting timed on `grid` at `size` pixels, in the order of the CSV rows.
std::vector<Setting> MakeSettings(vtkUnstructuredGrid* grid, const Options& o, int size);
}

#endif
