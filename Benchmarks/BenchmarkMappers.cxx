/*=========================================================================

  Program:   TiledRayCast
  Module:    BenchmarkMappers.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Speed against accuracy: renders one scene with many volume mappers in one process, same camera
// path, transfer function and image size, and writes one CSV row per (scene, mapper, setting,
// image size). See docs/benchmarks.md for the protocol.
//
//   BenchmarkMappers [options] <mesh.vtu | generated:RUNG> [...]
//     generated:RUNG    a rung made in memory (GeneratedMeshes.h: wavelet6_100m, gym6_300m, ...)
//     --size N          image side in pixels (repeatable; default 512)
//     --frames F        timed frames per setting, along a full turn of the camera (default 12)
//     --csv FILE        append rows to FILE (default: standard output); a header when new
//     --ours-only       only our default setting (the scaling runs on the dataset ladder)
//     --sweep quick|full|defaults|pipelines|default|buffers  our settings (default quick);
//                       "defaults" times only ours, over the fragment pipeline's tile sizes, tets
//                       per pass and occlusion-query intervals; "pipelines" only ours, each
//                       pipeline's default; "default" only our default (the ladder's largest
//                       rungs); "buffers" our default, then with the mesh split over 3 to 4
//                       and 5 to 8 texture buffers (what meshes above 134M tetrahedra cost)
//     --no-others       leave VTK's mappers out
//     --pt-only         of VTK's mappers, only the projected tetrahedra (large meshes and images)
//     --zsweep-max-tets T  ZSweep only up to T tets and 512 px (default 300000)
//     --resample R,R,.. resampling resolutions for resample + GPU ray cast (default 64,128,256)
//     --no-reference    skip the exact reference (error columns stay empty)
//     --order O         input (default), morton, morton-cells, morton-points or shuffled: the
//                       memory order of cells and points (BenchmarkMeshOrder.h); the scene is
//                       named mesh+O unless input
//     --rate R          also time ours while "interacting" at R frames per second: the window's
//                       desired update rate is R during the warm-up and the timed frames
//                       (AutoAdjustSampleDistances fits the rays to it), and the error is
//                       measured on the last view then ("compute interactive R/s")
//     --shade           shading on (vtkVolumeProperty::ShadeOn, the renderer's headlight): the
//                       scene is named mesh+shaded
//     --tf T            ramp (default: the scenes' ramp), band (opacity only in a band 2 % of
//                       the scalar range wide, at its middle) or spike (0.4 % wide): the scene
//                       is named mesh+T unless ramp, and ours is also timed without empty-space
//                       skipping ("compute no-skipping")
//
// Every setting: the first frame (mesh build, upload, shader compilation) is timed on its own,
// with the mapper's mesh build time and the host memory it peaked at beyond what the process held
// before (Linux: VmHWM after the peak was reset through /proc/self/clear_refs), per tetrahedron;
// then, after half a second of warm-up frames, F frames, each Render() followed by glFinish
// (WaitForCompletion), wall clock and GPU timer; the error is measured on the first view against
// vtkTetReferenceRenderer's exact image. Our rows also hold the median GPU time of each phase and
// of the mapper's whole Render(), its CPU time, the rays, the tets each walked and the per-pixel
// target memory: the mapper's statistics, read as a user reads them (SynchronousStatistics off,
// the default, so that the timed frames are the frames a user gets): each frame's statistics
// then hold the previous frame's GPU times and counts, which the medians do not mind. Settings of
// ours are named by pipeline; each pipeline's default setting is "compute default" and "fragment
// default".
#include "BenchmarkFrames.h"
#include "BenchmarkMapperSettings.h"
#include "BenchmarkMeshOrder.h"
#include "GeneratedMeshes.h"
#include "ProcessMemory.h"
#include "TiledRayCastSharedScenes.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderTimer.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTetReferenceRenderer.h"
#include "vtkTiledRayCastStatistics.h"
#include "vtkTiledRayCastVolumeMapper.h"
#include "vtkTimerLog.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using trcbench::ProcessMemory;
using trcbench::ResetPeakMemory;
using trcmappers::Options;
using trcmappers::Setting;

// One CSV row; NaN = not measured (written as an empty cell).
struct Row
{
  std::string Scene, Mesh, Mapper, Setting;
  vtkIdType Tets = 0;
  int Size = 0, Frames = 0;
  double MedianMs = NAN, MinMs = NAN, GpuMedianMs = NAN, FirstFrameMs = NAN, ResampleMs = NAN,
         TetsPerS = NAN, GpuBytesPerTet = NAN, Rmse = NAN, P999 = NAN, MaxErr = NAN,
         LostPixels = NAN, Layers = NAN, MedianPasses = NAN, MaxPasses = NAN;
  std::string Pipeline;
  double FirstHitMs = NAN, PeelingMs = NAN, RayCastingMs = NAN, CompositingMs = NAN, Rays = NAN,
         MeanSteps = NAN, MaxSteps = NAN, Entries = NAN, TargetBytesPerPixel = NAN,
         MapperGpuMs = NAN, MapperCpuMs = NAN, SampleDistance = NAN, MeshBuildMs = NAN,
         MeshUploadMs = NAN, HostPeakBytesPerTet = NAN;
};

const char* Header = "scene,mesh,tets,image_size,mapper,setting,frames,median_ms,min_ms,"
                     "gpu_median_ms,first_frame_ms,resample_ms,tets_per_s,gpu_bytes_per_tet,"
                     "rmse,p999,max_err,lost_pixels,layers,median_passes_per_tile,"
                     "max_passes_per_tile,pipeline,first_hit_ms,peeling_ms,ray_casting_ms,"
                     "compositing_ms,rays,mean_steps_per_ray,max_steps_per_ray,entries,"
                     "target_bytes_per_pixel,mapper_gpu_ms,mapper_cpu_ms,image_sample_distance,"
                     "mesh_build_ms,host_peak_bytes_per_tet,mesh_upload_ms";

std::string Cell(double v)
{
  if (std::isnan(v))
  {
    return "";
  }
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

void WriteRow(std::ostream& os, const Row& r)
{
  os << r.Scene << "," << r.Mesh << "," << r.Tets << "," << r.Size << "," << r.Mapper << ","
     << r.Setting << "," << r.Frames << "," << Cell(r.MedianMs) << "," << Cell(r.MinMs) << ","
     << Cell(r.GpuMedianMs) << "," << Cell(r.FirstFrameMs) << "," << Cell(r.ResampleMs) << ","
     << Cell(r.TetsPerS) << "," << Cell(r.GpuBytesPerTet) << "," << Cell(r.Rmse) << ","
     << Cell(r.P999) << "," << Cell(r.MaxErr) << "," << Cell(r.LostPixels) << "," << Cell(r.Layers)
     << "," << Cell(r.MedianPasses) << "," << Cell(r.MaxPasses) << "," << r.Pipeline << ","
     << Cell(r.FirstHitMs) << "," << Cell(r.PeelingMs) << "," << Cell(r.RayCastingMs) << ","
     << Cell(r.CompositingMs) << "," << Cell(r.Rays) << "," << Cell(r.MeanSteps) << ","
     << Cell(r.MaxSteps) << "," << Cell(r.Entries) << "," << Cell(r.TargetBytesPerPixel) << ","
     << Cell(r.MapperGpuMs) << "," << Cell(r.MapperCpuMs) << "," << Cell(r.SampleDistance) << ","
     << Cell(r.MeshBuildMs) << "," << Cell(r.HostPeakBytesPerTet) << "," << Cell(r.MeshUploadMs)
     << "\n";
}

// The median of the timed frames' values; NaN (an empty cell) for none.
double Median(const std::vector<double>& values)
{
  return trcbench::Median(values, NAN);
}

// The transfer function of every benchmark: the ramp of the tests' scenes over the scalar range,
// or a band or spike of it (--tf), unit distance 1/20 of the bounding-box diagonal
// (TiledRayCastSharedScenes.h).
vtkSmartPointer<vtkVolumeProperty> MakeProperty(vtkDataSet* grid, const std::string& tf)
{
  if (tf == "ramp")
  {
    return trcscene::MakePropertyFor(grid, 0.05);
  }
  double range[2];
  grid->GetPointData()->GetScalars()->GetRange(range);
  const double width = tf == "band" ? 0.02 : 0.004;
  return trcscene::MakeBandProperty(range, 0.5 - 0.5 * width, width, 0.05 * grid->GetLength());
}

// View i of the camera path: VTK's ResetCamera, then an elevation of 20 degrees and a turn.
void SetView(vtkRenderer* renderer, vtkDataSet* grid, int i, int frames)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0, 0, 1);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(30);
  renderer->ResetCamera(grid->GetBounds());
  camera->Azimuth(30.0 + 360.0 * i / std::max(1, frames));
  camera->Elevation(20);
  camera->OrthogonalizeViewUp();
  camera->Zoom(1.2);
  renderer->ResetCameraClippingRange(grid->GetBounds());
}

// The window's pixels as RGB bytes.
std::vector<unsigned char> ReadPixels(vtkRenderWindow* window, int size)
{
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetPixelData(0, 0, size - 1, size - 1, 0, pixels, 0);
  return std::vector<unsigned char>(pixels->GetPointer(0), pixels->GetPointer(0) + 3 * size * size);
}

struct Error
{
  double Rmse, P999, Max, Lost;
};

// Against the reference: RMSE, 99.9th percentile and maximum of the per-channel differences in
// 1/255, and pixels whose difference exceeds 32/255 in some channel (a ray lost or cut short).
Error Compare(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b)
{
  std::vector<int> d(a.size());
  double sum = 0;
  double lost = 0;
  for (size_t i = 0; i < a.size(); ++i)
  {
    d[i] = std::abs(int(a[i]) - int(b[i]));
    sum += double(d[i]) * d[i];
  }
  for (size_t p = 0; p + 2 < a.size(); p += 3)
  {
    lost += (d[p] > 32 || d[p + 1] > 32 || d[p + 2] > 32) ? 1 : 0;
  }
  std::vector<int> sorted = d;
  const size_t k = std::min(sorted.size() - 1, static_cast<size_t>(0.999 * sorted.size()));
  std::nth_element(sorted.begin(), sorted.begin() + k, sorted.end());
  const double p999 = sorted[k];
  const double mx = *std::max_element(d.begin(), d.end());
  return { std::sqrt(sum / d.size()), p999, mx, lost };
}

// The options of the header (Options' defaults where not given); false with a message on a bad
// one or no mesh.
bool ParseOptions(int argc, char* argv[], Options& o)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto next = [&]() -> std::string { return i + 1 < argc ? argv[++i] : ""; };
    if (a == "--size")
      o.Sizes.push_back(std::max(16, atoi(next().c_str())));
    else if (a == "--frames")
      o.Frames = std::max(1, atoi(next().c_str()));
    else if (a == "--csv")
      o.Csv = next();
    else if (a == "--ours-only")
      o.OursOnly = true;
    else if (a == "--no-others")
      o.Others = false;
    else if (a == "--pt-only")
      o.ProjectedTetrahedraOnly = true;
    else if (a == "--sweep")
    {
      o.Sweep = next();
      if (o.Sweep != "quick" && o.Sweep != "full" && o.Sweep != "defaults" &&
        o.Sweep != "pipelines" && o.Sweep != "default" && o.Sweep != "buffers")
      {
        std::cerr << "--sweep takes quick, full, defaults, pipelines, default or buffers\n";
        return false;
      }
    }
    else if (a == "--zsweep-max-tets")
      o.ZSweepMaxTets = atoll(next().c_str());
    else if (a == "--resample")
    {
      o.Resample.clear();
      std::stringstream list(next());
      std::string item;
      while (std::getline(list, item, ','))
      {
        o.Resample.push_back(atoi(item.c_str()));
      }
    }
    else if (a == "--no-reference")
      o.Reference = false;
    else if (a == "--order")
    {
      o.Order = next();
      if (!IsMeshOrder(o.Order))
      {
        std::cerr << "--order takes input, morton, morton-cells, morton-points or shuffled\n";
        return false;
      }
    }
    else if (a == "--shade")
      o.Shade = true;
    else if (a == "--rate")
      o.Rate = std::max(0.0, atof(next().c_str()));
    else if (a == "--tf")
    {
      o.TransferFunction = next();
      if (o.TransferFunction != "ramp" && o.TransferFunction != "band" &&
        o.TransferFunction != "spike")
      {
        std::cerr << "--tf takes ramp, band or spike\n";
        return false;
      }
    }
    else if (!a.empty() && a[0] == '-')
    {
      std::cerr << "unknown option " << a << "\n";
      return false;
    }
    else
      o.Meshes.push_back(a);
  }
  if (o.Meshes.empty())
  {
    std::cerr << "usage: " << argv[0] << " [options] <mesh.vtu> ... (see the source's header)\n";
    return false;
  }
  if (o.Sizes.empty())
  {
    o.Sizes.push_back(512);
  }
  return true;
}

// The exact image of the first view of `grid` at `size` x `size` pixels, as 8-bit RGB.
std::vector<unsigned char> ExactImage(vtkRenderer* renderer, vtkUnstructuredGrid* grid,
  vtkVolumeProperty* property, const Options& o, int size, const std::string& scene)
{
  std::vector<unsigned char> reference;
  SetView(renderer, grid, 0, o.Frames);
  vtkNew<vtkTetReferenceRenderer> exact;
  exact->SetInputData(grid);
  exact->SetVolumeProperty(property);
  exact->SetCamera(renderer->GetActiveCamera());
  exact->SetImageSize(size, size);
  exact->SetLights(renderer->GetLights()); // the headlight of the first Render()
  exact->SetTwoSidedLighting(renderer->GetTwoSidedLighting());
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  exact->Render();
  timer->StopTimer();
  vtkNew<vtkImageData> image;
  const double background[3] = { 0, 0, 0 };
  vtkTetReferenceRenderer::ConvertToUnsignedChar(exact->GetOutput(), background, image);
  auto* scalars = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  reference.assign(scalars->GetPointer(0), scalars->GetPointer(0) + 3 * size * size);
  std::cerr << scene << " " << size << "^2: exact reference in " << timer->GetElapsedTime()
            << " s\n";
  return reference;
}

// Our mapper's columns of `row`: its statistics of the last frame and the medians of the timed
// frames' phases, steps, times and sample distances.
void FillOurColumns(vtkTiledRayCastStatistics* stats, const std::vector<double> phases[4],
  const std::vector<double>& steps, const std::vector<double>& mapperGpu,
  const std::vector<double>& mapperCpu, const std::vector<double>& distances, int size,
  const std::string& label, Row& row)
{
  row.GpuBytesPerTet = double(stats->GetTotalGPUBytes()) / row.Tets;
  row.Layers = stats->GetNumberOfLayers();
  row.MedianPasses = stats->GetMedianPassesPerTile();
  row.MaxPasses = stats->GetMaximumPassesPerTile();
  row.Pipeline = stats->GetPipeline() ? stats->GetPipeline() : "";
  row.FirstHitMs = Median(phases[0]);
  row.PeelingMs = Median(phases[1]);
  row.RayCastingMs = Median(phases[2]);
  row.CompositingMs = Median(phases[3]);
  row.MapperGpuMs = Median(mapperGpu);
  row.MapperCpuMs = Median(mapperCpu);
  row.SampleDistance = Median(distances);
  row.Rays = static_cast<double>(stats->GetNumberOfRays());
  if (row.Pipeline == "Compute") // the fragment pipeline counts no steps or entries
  {
    row.MeanSteps = Median(steps);
    row.MaxSteps = static_cast<double>(stats->GetMaximumStepsPerRay());
    row.Entries = static_cast<double>(stats->GetNumberOfEntries());
  }
  row.TargetBytesPerPixel = double(stats->GetRenderTargetBytes()) / (double(size) * size);
  if (!stats->GetRendered())
  {
    std::cerr << label << ": nothing rendered\n";
  }
}

// Times `setting` on the scene of `renderer` (its first frame, a warm-up, then the timed
// frames along the camera path) into `row`, with its error against `reference` where there is one.
void TimeSetting(const Setting& setting, vtkRenderWindow* window, vtkRenderer* renderer,
  vtkUnstructuredGrid* grid, vtkVolumeProperty* property, const Options& o, int size,
  const std::vector<unsigned char>& reference, const std::string& scene, Row& row)
{
  double prepareMs = NAN;
  vtkSmartPointer<vtkAbstractVolumeMapper> mapper = setting.Make(prepareMs);
  row.ResampleMs = prepareMs;
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  renderer->AddVolume(volume);

  // First frame: everything the mapper prepares, and the host memory it takes to.
  SetView(renderer, grid, 0, o.Frames);
  const double before = ProcessMemory("VmRSS");
  const bool peakReset = ResetPeakMemory();
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  window->Render();
  window->WaitForCompletion();
  timer->StopTimer();
  row.FirstFrameMs = 1000.0 * timer->GetElapsedTime();
  if (peakReset)
  {
    row.HostPeakBytesPerTet = (ProcessMemory("VmHWM") - before) / row.Tets;
  }
  auto* ourMapper = vtkTiledRayCastVolumeMapper::SafeDownCast(mapper);
  if (ourMapper)
  {
    row.MeshBuildMs = 1000.0 * ourMapper->GetStatistics()->GetMeshBuildTime();
    row.MeshUploadMs = 1000.0 * ourMapper->GetStatistics()->GetMeshUploadTime();
  }

  // Interacting: the rate for the warm-up (the sample distance settles) and timed frames.
  window->SetDesiredUpdateRate(setting.Rate > 0 ? setting.Rate : 0.0001);
  auto measureError = [&]()
  {
    window->Render();
    const Error e = Compare(ReadPixels(window, size), reference);
    row.Rmse = e.Rmse;
    row.P999 = e.P999;
    row.MaxErr = e.Max;
    row.LostPixels = e.Lost;
  };
  if (!reference.empty() && setting.Rate <= 0)
  {
    measureError();
  }

  // Warm-up along the same path until half a second has passed: a GPU left idle while
  // the CPU computed the reference lowers its clocks, and short frames would be timed
  // before they rise again.
  timer->StartTimer();
  for (int f = 0; f < 1000; ++f)
  {
    SetView(renderer, grid, f, o.Frames);
    window->Render();
    window->WaitForCompletion();
    timer->StopTimer();
    if (f >= 1 && timer->GetElapsedTime() > 0.5)
    {
      break;
    }
  }

  std::vector<double> wall, gpu;
  std::vector<double> phases[4], steps, mapperGpu, mapperCpu, distances;
  auto* ours = vtkTiledRayCastVolumeMapper::SafeDownCast(mapper);
  vtkOpenGLRenderTimer timerObject; // not a vtkObject
  vtkOpenGLRenderTimer* gpuTimer = &timerObject;
  for (int f = 0; f < o.Frames; ++f)
  {
    SetView(renderer, grid, f, o.Frames);
    timer->StartTimer();
    gpuTimer->Reset();
    gpuTimer->Start();
    window->Render();
    gpuTimer->Stop();
    window->WaitForCompletion();
    timer->StopTimer();
    wall.push_back(1000.0 * timer->GetElapsedTime());
    if (gpuTimer->Ready())
    {
      gpu.push_back(gpuTimer->GetElapsedMilliseconds());
    }
    if (ours)
    {
      vtkTiledRayCastStatistics* stats = ours->GetStatistics();
      phases[0].push_back(stats->GetFirstHitTime());
      phases[1].push_back(stats->GetPeelingTime());
      phases[2].push_back(stats->GetRayCastingTime());
      phases[3].push_back(stats->GetCompositingTime());
      steps.push_back(stats->GetMeanStepsPerRay());
      mapperGpu.push_back(stats->GetTotalGPUTime());
      mapperCpu.push_back(1000.0 * stats->GetRenderTime());
      distances.push_back(stats->GetImageSampleDistance());
    }
  }
  gpuTimer->ReleaseGraphicsResources();
  if (!reference.empty() && setting.Rate > 0)
  {
    SetView(renderer, grid, 0, o.Frames); // the reference's view, at the interactive rate
    measureError();
  }
  window->SetDesiredUpdateRate(0.0001);
  row.MedianMs = Median(wall);
  row.MinMs = *std::min_element(wall.begin(), wall.end());
  row.GpuMedianMs = Median(gpu);
  row.TetsPerS = row.Tets / (row.MedianMs / 1000.0);
  if (ours)
  {
    FillOurColumns(ours->GetStatistics(), phases, steps, mapperGpu, mapperCpu, distances, size,
      scene + " " + setting.Name, row);
  }
  else if (setting.Mapper == "resample_gpu")
  {
    const int r = atoi(setting.Name.c_str() + 3);
    row.GpuBytesPerTet = (4.0 + 1.0) * r * r * r / row.Tets; // float scalars + mask
  }
  renderer->RemoveVolume(volume); // releases its graphics resources
}

// The mesh of a .vtu file, or of a generated rung ("generated:RUNG", made in memory and checked
// against its expected counts); null with a message when neither works.
vtkSmartPointer<vtkUnstructuredGrid> ReadOrGenerate(const std::string& path, bool mortonPoints)
{
  const std::string prefix = "generated:";
  if (path.compare(0, prefix.size(), prefix) != 0)
  {
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    return reader->GetOutput();
  }
  const generated::Rung* rung = generated::FindRung(path.substr(prefix.size()));
  if (!rung)
  {
    std::cerr << path << ": no such generated rung (GeneratedMeshes.cxx lists them)\n";
    return nullptr;
  }
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  vtkSmartPointer<vtkUnstructuredGrid> grid = generated::MakeRung(*rung, mortonPoints);
  timer->StopTimer();
  if (grid)
  {
    std::cerr << rung->Name << ": " << rung->Tetrahedra << " tetrahedra made in memory in "
              << timer->GetElapsedTime() << " s, process at " << ProcessMemory("VmRSS") / 1e9
              << " GB\n";
  }
  return grid;
}
} // namespace

int main(int argc, char* argv[])
{
  Options o;
  if (!ParseOptions(argc, argv, o))
  {
    return EXIT_FAILURE;
  }

  std::ofstream file;
  std::ostream* out = &std::cout;
  if (!o.Csv.empty())
  {
    const bool exists = std::ifstream(o.Csv).good();
    file.open(o.Csv, std::ios::app);
    out = &file;
    if (!exists)
    {
      file << Header << "\n";
    }
  }
  else
  {
    std::cout << Header << "\n";
  }

  for (const std::string& path : o.Meshes)
  {
    // A generated rung is made in morton-points order directly (reordering it would take
    // minutes); the other orders go through ReorderMesh.
    const bool generated = path.rfind("generated:", 0) == 0;
    const bool mortonPoints = generated && o.Order == "morton-points";
    vtkSmartPointer<vtkUnstructuredGrid> input = ReadOrGenerate(path, mortonPoints);
    if (!input)
    {
      return EXIT_FAILURE;
    }
    vtkSmartPointer<vtkUnstructuredGrid> ordered =
      ReorderMesh(input, mortonPoints ? std::string("input") : o.Order);
    input = nullptr;
    vtkUnstructuredGrid* grid = ordered;
    if (grid->GetNumberOfCells() == 0 || !grid->GetPointData()->GetScalars())
    {
      std::cerr << path << ": no cells or no point scalars; skipped\n";
      continue;
    }
    std::string mesh = path.substr(path.find_last_of("/:") + 1);
    const std::string scene = mesh.substr(0, mesh.find('.')) +
      (o.Order == "input" ? "" : "+" + o.Order) +
      (o.TransferFunction == "ramp" ? "" : "+" + o.TransferFunction) + (o.Shade ? "+shaded" : "");
    vtkSmartPointer<vtkVolumeProperty> property = MakeProperty(grid, o.TransferFunction);
    property->SetShade(o.Shade ? 1 : 0);

    for (int size : o.Sizes)
    {
      vtkNew<vtkRenderer> renderer;
      renderer->SetBackground(0, 0, 0);
      vtkNew<vtkRenderWindow> window;
      window->SetOffScreenRendering(1);
      window->SetMultiSamples(0);
      window->SetSize(size, size);
      window->AddRenderer(renderer);
      window->Render();

      // The exact image of the first view.
      std::vector<unsigned char> reference;
      if (o.Reference)
      {
        reference = ExactImage(renderer, grid, property, o, size, scene);
      }

      for (const Setting& setting : MakeSettings(grid, o, size))
      {
        Row row;
        row.Scene = scene;
        row.Mesh = mesh;
        row.Tets = grid->GetNumberOfCells();
        row.Size = size;
        row.Mapper = setting.Mapper;
        row.Setting = setting.Name;
        row.Frames = o.Frames;

        TimeSetting(setting, window, renderer, grid, property, o, size, reference, scene, row);
        WriteRow(*out, row);
        out->flush();
        std::cerr << scene << " " << size << "^2 " << setting.Mapper << " [" << setting.Name
                  << "]: median " << row.MedianMs << " ms, first " << row.FirstFrameMs
                  << " ms, RMSE " << row.Rmse << "\n";
      }
    }
  }
  return EXIT_SUCCESS;
}
