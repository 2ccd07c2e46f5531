/*=========================================================================

  Program:   TiledRayCast
  Module:    BenchmarkTetMeshBuild.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Times vtkTetMeshBuilder and the two GPU layouts on tetrahedral meshes and prints, per
// dataset: tetrahedra, full-build time and rate (builder + layout) for the compact and the paper
// layout, the same with spatial ordering, the points-only rebuild (deforming mesh), the first
// build of a fresh builder (cold memory), and bytes per tetrahedron of both layouts. Every
// figure is the median of several runs.
//
// Usage: BenchmarkTetMeshBuild [--runs N] [--threads N] [--phases] [directory [file.vtu ...]]
// The directory defaults to the source tree's Testing/Data/Meshes and the files to all of its
// .vtu files. --phases adds, per dataset, the median time of each phase of a full build.
//
//        BenchmarkTetMeshBuild [--threads N] [--scratch-limit BYTES] --generated RUNG [RUNG ...]
// Rungs made in memory (GeneratedMeshes.h: wavelet6_100m ... wavelet6_1b), too large for the
// table above: one build each as the mapper makes it (spatial and point ordering, compact
// layout, scratch freed by stage), printed as CSV: the time to make the grid, the build's time
// and rate, its phases, and the host's peak beyond the grid (VmHWM, ProcessMemory.h).
// --scratch-limit sets the builder's MaximumKeptScratchMemory (0: a small mesh built as a huge
// one is, its faces matched in four passes).
#include "GeneratedMeshes.h"
#include "ProcessMemory.h"
#include "vtkDirectory.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"
#include "vtkTetMesh.h"
#include "vtkTetMeshBuilder.h"
#include "vtkTetMeshCompactLayout.h"
#include "vtkTetMeshPaperLayout.h"
#include "vtkTetMeshValidationReport.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace
{
double Median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// Median wall-clock seconds of `runs` calls of f (each preceded by `prepare`, untimed), and in
// `cpu` the median processor time of the whole process (all threads) over the same calls: on a
// machine shared with other work, the wall clock shows the contention and the processor time
// much less so.
double Time(int runs, const std::function<void()>& prepare, const std::function<void()>& f,
  double* cpu = nullptr)
{
  std::vector<double> times, cpuTimes;
  for (int r = 0; r < runs; ++r)
  {
    prepare();
    const std::clock_t cpuStart = std::clock();
    const double start = vtkTimerLog::GetUniversalTime();
    f();
    times.push_back(vtkTimerLog::GetUniversalTime() - start);
    cpuTimes.push_back(static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC);
  }
  if (cpu)
  {
    *cpu = Median(cpuTimes);
  }
  return Median(times);
}

// Moves every point: a translation by +-2^-20 of the largest extent (rounded to a power of two,
// the sign alternating between calls). The points are doubles holding float values, so the
// sums are exact and every difference of points, hence every orientation, is unchanged: the
// exactly flat tetrahedra of torus_vistrails stay flat and no call falls back to a full build.
// The work of the points-only path does not depend on how the points move.
void Move(vtkUnstructuredGrid* grid, const std::vector<double>& original, int call)
{
  vtkPoints* points = grid->GetPoints();
  const double* b = grid->GetBounds();
  const double extent = std::max({ b[1] - b[0], b[3] - b[2], b[5] - b[4], 1e-300 });
  const double amount = (call % 2 ? 1.0 : -1.0) * std::exp2(std::floor(std::log2(extent)) - 20);
  const vtkIdType n = points->GetNumberOfPoints();
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->SetPoint(
      i, original[3 * i] + amount, original[3 * i + 1] + amount, original[3 * i + 2] + amount);
  }
  points->Modified();
}

// Milliseconds per vtkTimerLog event name, from matching start and end events.
std::map<std::string, double> EventTimes()
{
  std::map<std::string, double> started, total;
  for (int i = 0; i < vtkTimerLog::GetNumberOfEvents(); ++i)
  {
    const std::string name = vtkTimerLog::GetEventString(i);
    if (vtkTimerLog::GetEventType(i) == vtkTimerLogEntry::START)
    {
      started[name] = vtkTimerLog::GetEventWallTime(i);
    }
    else if (vtkTimerLog::GetEventType(i) == vtkTimerLogEntry::END && started.count(name))
    {
      total[name] += 1e3 * (vtkTimerLog::GetEventWallTime(i) - started[name]);
    }
  }
  return total;
}
// The .vtu files of `directory`, sorted; false where it cannot be opened.
bool ListMeshes(const std::string& directory, std::vector<std::string>& files)
{
  vtkNew<vtkDirectory> listing;
  if (!listing->Open(directory.c_str()))
  {
    std::fprintf(stderr, "cannot open the directory %s\n", directory.c_str());
    return false;
  }
  for (vtkIdType i = 0; i < listing->GetNumberOfFiles(); ++i)
  {
    const std::string name = listing->GetFile(i);
    if (name.size() > 4 && name.substr(name.size() - 4) == ".vtu")
    {
      files.push_back(name);
    }
  }
  std::sort(files.begin(), files.end());
  return true;
}

// The median time of each phase of the full build (vtkTimerLog events), on one line.
void PrintPhases(
  vtkTetMeshBuilder* builder, vtkTetMeshCompactLayout* compact, vtkUnstructuredGrid* grid, int runs)
{
  std::map<std::string, std::vector<double>> perPhase;
  vtkTimerLog::LoggingOn();
  for (int r = 0; r < runs; ++r)
  {
    builder->Invalidate();
    vtkTimerLog::ResetLog();
    compact->Build(builder->Build(grid));
    for (const auto& phase : EventTimes())
    {
      perPhase[phase.first].push_back(phase.second);
    }
  }
  vtkTimerLog::LoggingOff();
  std::printf("|  phases of the full build, ms: ");
  for (const auto& phase : perPhase)
  {
    std::printf(" %s %.1f;", phase.first.c_str(), Median(phase.second));
  }
  std::printf(" |\n");
}

// The table's line of `grid` (double-precision points): cold and warm full builds, with each
// layout and with spatial ordering, points-only updates, and the layouts' sizes; with `phases`,
// the phases of the full build.
void BenchmarkMesh(vtkUnstructuredGrid* grid, const std::string& file, int runs, bool phases)
{
  std::vector<double> original(3 * static_cast<size_t>(grid->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    grid->GetPoints()->GetPoint(i, original.data() + 3 * i);
  }

  // First build of a fresh builder and layout: memory not yet touched (page faults included).
  std::vector<double> cold;
  for (int r = 0; r < runs; ++r)
  {
    vtkNew<vtkTetMeshBuilder> builder;
    vtkNew<vtkTetMeshCompactLayout> layout;
    const double start = vtkTimerLog::GetUniversalTime();
    layout->Build(builder->Build(grid));
    cold.push_back(vtkTimerLog::GetUniversalTime() - start);
  }
  const double coldTime = Median(cold);

  vtkNew<vtkTetMeshBuilder> builder;
  vtkNew<vtkTetMeshCompactLayout> compact;
  vtkNew<vtkTetMeshPaperLayout> paper;
  vtkTetMesh* mesh = builder->Build(grid);
  if (!mesh->GetReport()->GetUsable())
  {
    std::fprintf(stderr, "%s: %s\n", file.c_str(), mesh->GetReport()->GetErrorMessage());
    return;
  }
  const double numTets = static_cast<double>(mesh->GetNumberOfTetrahedra());
  compact->Build(mesh);
  paper->Build(mesh);

  auto invalidate = [&]() { builder->Invalidate(); };
  double compactCpu = 0.0;
  const double compactTime = Time(
    runs, invalidate, [&]() { compact->Build(builder->Build(grid)); }, &compactCpu);
  const double paperTime = Time(runs, invalidate, [&]() { paper->Build(builder->Build(grid)); });
  builder->SpatialOrderingOn();
  const double mortonTime = Time(runs, invalidate, [&]() { compact->Build(builder->Build(grid)); });
  builder->SpatialOrderingOff();
  compact->Build(builder->Build(grid));

  int call = 0;
  bool pointsPath = true;
  const double pointsTime = Time(
    runs, [&]() { Move(grid, original, ++call); },
    [&]()
    {
      compact->Update(builder->Build(grid));
      pointsPath = pointsPath && builder->GetLastRebuild() == vtkTetMeshBuilder::RebuildPoints;
    });
  if (!pointsPath)
  {
    std::fprintf(stderr, "%s: the points-only path was not taken\n", file.c_str());
  }
  paper->Build(mesh);

  std::printf("| %s | %.0f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | "
              "%.1f | %.1f | %.1f | %.2f | %.2f |\n",
    file.c_str(), numTets, 1e3 * compactTime, numTets / compactTime / 1e6, 1e3 * compactCpu,
    1e3 * paperTime, numTets / paperTime / 1e6, 1e3 * mortonTime, numTets / mortonTime / 1e6,
    1e3 * pointsTime, numTets / pointsTime / 1e6, 1e3 * coldTime, numTets / coldTime / 1e6,
    paper->GetBytesPerTet(), paper->GetBytesPerTetWithBoundary(), compact->GetBytesPerTet(),
    compact->GetBytesPerTetWithBoundary());
  if (phases)
  {
    PrintPhases(builder, compact, grid, runs);
  }
}

// One rung made in memory, built once as the mapper builds it: a CSV line (header first).
bool BenchmarkGeneratedRung(const std::string& name, bool header, vtkIdType scratchLimit)
{
  const generated::Rung* rung = generated::FindRung(name);
  if (!rung)
  {
    std::fprintf(
      stderr, "%s: no such generated rung (GeneratedMeshes.cxx lists them)\n", name.c_str());
    return false;
  }
  double start = vtkTimerLog::GetUniversalTime();
  vtkSmartPointer<vtkUnstructuredGrid> grid = generated::MakeRung(*rung);
  const double makeTime = vtkTimerLog::GetUniversalTime() - start;
  if (!grid)
  {
    return false;
  }
  const double gridBytes = trcbench::ProcessMemory("VmRSS");
  const bool peakReset = trcbench::ResetPeakMemory();
  vtkNew<vtkTetMeshBuilder> builder;
  builder->SpatialOrderingOn();
  builder->PointOrderingOn();
  if (scratchLimit >= 0)
  {
    builder->SetMaximumKeptScratchMemory(scratchLimit);
  }
  vtkNew<vtkTetMeshCompactLayout> layout;
  vtkTimerLog::ResetLog();
  vtkTimerLog::LoggingOn();
  start = vtkTimerLog::GetUniversalTime();
  vtkTetMesh* mesh = builder->Build(grid);
  layout->Build(mesh);
  const double buildTime = vtkTimerLog::GetUniversalTime() - start;
  vtkTimerLog::LoggingOff();
  const double tets = static_cast<double>(mesh->GetNumberOfTetrahedra());
  const double peak = peakReset ? (trcbench::ProcessMemory("VmHWM") - gridBytes) / tets : NAN;
  const double after = (trcbench::ProcessMemory("VmRSS") - gridBytes) / tets;
  const std::map<std::string, double> phases = EventTimes();
  if (header)
  {
    std::printf("rung,threads,tets,points,make_grid_s,build_s,build_mtet_per_s,"
                "host_peak_bytes_per_tet,host_after_bytes_per_tet,usable,phases_ms\n");
  }
  std::string phaseList;
  for (const auto& phase : phases)
  {
    char cell[160];
    std::snprintf(cell, sizeof(cell), "%s%s=%.0f", phaseList.empty() ? "" : ";",
      phase.first.c_str(), phase.second);
    phaseList += cell;
  }
  std::printf("%s,%d,%.0f,%lld,%.2f,%.2f,%.2f,%.1f,%.1f,%d,\"%s\"\n", name.c_str(),
    vtkSMPTools::GetEstimatedNumberOfThreads(), tets,
    static_cast<long long>(mesh->GetNumberOfPoints()), makeTime, buildTime, tets / buildTime / 1e6,
    peak, after, mesh->GetReport()->GetUsable() ? 1 : 0, phaseList.c_str());
  std::fflush(stdout);
  return mesh->GetReport()->GetUsable();
}

} // namespace

int main(int argc, char* argv[])
{
  int runs = 7;
  int threads = 0;
  vtkIdType scratchLimit = -1; // the builder's default
  bool phases = false;
  bool generatedRungs = false;
  std::string directory = TRC_MESH_DATA_DIRECTORY;
  std::vector<std::string> files;
  std::vector<std::string> positional;
  for (int a = 1; a < argc; ++a)
  {
    if (!std::strcmp(argv[a], "--runs") && a + 1 < argc)
    {
      runs = std::max(1, std::atoi(argv[++a]));
    }
    else if (!std::strcmp(argv[a], "--threads") && a + 1 < argc)
    {
      threads = std::atoi(argv[++a]);
    }
    else if (!std::strcmp(argv[a], "--phases"))
    {
      phases = true;
    }
    else if (!std::strcmp(argv[a], "--generated"))
    {
      generatedRungs = true;
    }
    else if (!std::strcmp(argv[a], "--scratch-limit") && a + 1 < argc)
    {
      scratchLimit = std::atoll(argv[++a]);
    }
    else if (!std::strcmp(argv[a], "--help") || !std::strcmp(argv[a], "-h"))
    {
      std::printf("usage: %s [--runs N] [--threads N] [--phases] [data directory [file.vtu ...]]\n"
                  "       %s [--threads N] [--scratch-limit BYTES] --generated RUNG [RUNG ...]\n",
        argv[0], argv[0]);
      return EXIT_SUCCESS;
    }
    else
    {
      positional.emplace_back(argv[a]);
    }
  }
  // The first positional argument is the directory, the others are file names in it.
  if (!positional.empty())
  {
    directory = positional[0];
    files.assign(positional.begin() + 1, positional.end());
  }
  vtkSMPTools::Initialize(threads);
  if (generatedRungs)
  {
    bool ok = !positional.empty();
    for (size_t r = 0; r < positional.size(); ++r)
    {
      ok = BenchmarkGeneratedRung(positional[r], r == 0, scratchLimit) && ok;
    }
    return ok ? EXIT_SUCCESS : EXIT_FAILURE;
  }
  if (files.empty())
  {
    if (!ListMeshes(directory, files))
    {
      return EXIT_FAILURE;
    }
  }

  std::printf("vtkTetMeshBuilder benchmark: SMP backend %s, %d threads, median of %d runs\n",
    vtkSMPTools::GetBackend(), vtkSMPTools::GetEstimatedNumberOfThreads(), runs);
  std::printf("times in ms (wall clock; cpu = processor time of all threads), rates in million "
              "tetrahedra per second; full build = builder + layout\n\n");
  std::printf("| dataset | tets | full, compact | Mtet/s | cpu | full, paper | Mtet/s | full, "
              "compact, Morton | Mtet/s | points only | Mtet/s | first build | Mtet/s | paper "
              "B/tet | +boundary | compact B/tet | +boundary |\n");
  std::printf(
    "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");

  for (const std::string& file : files)
  {
    const std::string path = directory + "/" + file;
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    vtkNew<vtkUnstructuredGrid> grid;
    grid->DeepCopy(reader->GetOutput());
    // Double-precision points (see Move()).
    vtkNew<vtkPoints> doublePoints;
    doublePoints->SetDataTypeToDouble();
    doublePoints->DeepCopy(grid->GetPoints());
    grid->SetPoints(doublePoints);
    if (grid->GetNumberOfCells() == 0)
    {
      std::fprintf(stderr, "%s: no cells (not read?)\n", path.c_str());
      continue;
    }
    BenchmarkMesh(grid, file, runs, phases);
    std::fflush(stdout);
  }
  return EXIT_SUCCESS;
}
