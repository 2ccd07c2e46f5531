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
//   BenchmarkMappers [options] <mesh.vtu> [<mesh.vtu> ...]
//     --size N          image side in pixels (repeatable; default 512)
//     --frames F        timed frames per setting, along a full turn of the camera (default 12)
//     --csv FILE        append rows to FILE (default: standard output); a header when new
//     --ours-only       only our default setting (the scaling runs on the dataset ladder)
//     --sweep quick|full|defaults|pipelines  our settings (default quick); "defaults" times
//                       only ours, over the fragment pipeline's tile sizes, tets per pass and
//                       occlusion-query intervals; "pipelines" only ours, each pipeline's default
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
// Every setting: the first frame (mesh build, upload, shader compilation) is timed on its own;
// then, after half a second of warm-up frames, F frames, each Render() followed by glFinish
// (WaitForCompletion), wall clock and GPU timer; the error is measured on the first view against
// vtkTetReferenceRenderer's exact image. Our rows also hold the median GPU time of each phase and
// of the mapper's whole Render(), its CPU time, the rays, the tets each walked and the per-pixel
// target memory: the mapper's statistics, read as a user reads them (SynchronousStatistics off,
// the default, so that the timed frames are the frames a user gets): each frame's statistics
// then hold the previous frame's GPU times and counts, which the medians do not mind. Settings of
// ours are named by pipeline; each pipeline's default setting is "compute default" and "fragment
// default".
#include "BenchmarkMeshOrder.h"
#include "TiledRayCastSharedScenes.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderTimer.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkProjectedTetrahedraMapper.h"
#include "vtkRenderer.h"
#include "vtkResampleToImage.h"
#include "vtkSmartPointer.h"
#include "vtkTetReferenceRenderer.h"
#include "vtkTiledRayCastStatistics.h"
#include "vtkTiledRayCastVolumeMapper.h"
#include "vtkTimerLog.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridVolumeRayCastMapper.h"
#include "vtkUnstructuredGridVolumeZSweepMapper.h"
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
struct Options
{
  std::vector<int> Sizes;
  int Frames = 12;
  std::string Csv;
  bool OursOnly = false;
  bool Others = true;
  bool ProjectedTetrahedraOnly = false;
  std::string Sweep = "quick"; // quick, full or defaults
  vtkIdType ZSweepMaxTets = 300000;
  std::vector<int> Resample = { 64, 128, 256 };
  bool Reference = true;
  std::string Order = "input";
  std::string TransferFunction = "ramp";
  double Rate = 0;
  bool Shade = false;
  std::vector<std::string> Meshes;
};

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
         MapperGpuMs = NAN, MapperCpuMs = NAN, SampleDistance = NAN;
};

const char* Header = "scene,mesh,tets,image_size,mapper,setting,frames,median_ms,min_ms,"
                     "gpu_median_ms,first_frame_ms,resample_ms,tets_per_s,gpu_bytes_per_tet,"
                     "rmse,p999,max_err,lost_pixels,layers,median_passes_per_tile,"
                     "max_passes_per_tile,pipeline,first_hit_ms,peeling_ms,ray_casting_ms,"
                     "compositing_ms,rays,mean_steps_per_ray,max_steps_per_ray,entries,"
                     "target_bytes_per_pixel,mapper_gpu_ms,mapper_cpu_ms,image_sample_distance";

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
     << Cell(r.MapperGpuMs) << "," << Cell(r.MapperCpuMs) << "," << Cell(r.SampleDistance) << "\n";
}

double Median(std::vector<double> v)
{
  if (v.empty())
  {
    return NAN;
  }
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
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

// A setting: a name, a mapper family, and how to make its mapper (and, for resampling, the
// time it took).
struct Setting
{
  std::string Mapper, Name;
  std::function<vtkSmartPointer<vtkAbstractVolumeMapper>(double& prepareMs)> Make;
  double Rate = 0; // the window's desired update rate while timed (0: VTK's still rate)
};

using M = vtkTiledRayCastVolumeMapper;

// Our mapper of `grid` in the pipeline that `name` starts with ("compute ...": the compute
// pipeline, any other the fragment pipeline), with these settings; `table` > 0 sets the tables'
// scalar size (and half of it as their length size).
Setting Ours(vtkUnstructuredGrid* grid, const std::string& name, int mode, int layout, int n,
  int tile, int table, int queryInterval = 4, bool skipping = true)
{
  const int pipeline = name.rfind("compute", 0) == 0 ? M::COMPUTE_PIPELINE : M::FRAGMENT_PIPELINE;
  return { "ours", name,
    [=](double&)
    {
      auto m = vtkSmartPointer<vtkTiledRayCastVolumeMapper>::New();
      m->SetInputData(grid);
      m->SetPipeline(pipeline);
      m->SetIntegrationMode(mode);
      m->SetMeshLayout(layout);
      m->SetTetsPerPass(n);
      m->SetTileSize(tile);
      m->SetOcclusionQueryInterval(queryInterval);
      m->SetEmptySpaceSkipping(skipping);
      if (table > 0)
      {
        m->SetPreIntegrationTableScalarSize(table);
        m->SetPreIntegrationTableLengthSize(table / 2);
      }
      return vtkSmartPointer<vtkAbstractVolumeMapper>(m);
    } };
}

// --sweep defaults, the choice of defaults: tile size with one unlimited pass per layer, then
// the paper's bounded passes (N tets each) with their occlusion queries every K passes.
std::vector<Setting> DefaultsSweep(vtkUnstructuredGrid* grid)
{
  std::vector<Setting> settings;
  const int p = M::PARTIAL_PRE_INTEGRATION, c = M::COMPACT_LAYOUT;
  for (int tile : { 64, 128, 256, 512, 0 })
  {
    settings.push_back(Ours(grid,
      "fragment partial compact N0 T" + (tile ? std::to_string(tile) : std::string("all")), p, c, 0,
      tile, 0));
  }
  for (int n : { 1, 4, 16, 64 })
  {
    settings.push_back(Ours(
      grid, "fragment partial compact N" + std::to_string(n) + " T256 K4", p, c, n, 256, 0, 4));
  }
  settings.push_back(Ours(grid, "fragment partial compact N16 T256 K1", p, c, 16, 256, 0, 1));
  settings.push_back(Ours(grid, "fragment partial compact N16 T256 K16", p, c, 16, 256, 0, 16));
  return settings;
}

// Our settings of the other sweeps (quick, full, pipelines; only the first ones with
// --ours-only): the mapper's defaults, the automatic integration mode (the cheapest within 1/255
// of exact) and the compact layout, with partial pre-integration, exact, next to them.
std::vector<Setting> OurSettings(vtkUnstructuredGrid* grid, const Options& o)
{
  std::vector<Setting> settings;
  auto ours = [&](const std::string& name, int mode, int layout, int n, int tile, int table,
                int queryInterval = 4, bool skipping = true)
  { settings.push_back(Ours(grid, name, mode, layout, n, tile, table, queryInterval, skipping)); };
  const int partial = M::PARTIAL_PRE_INTEGRATION, compact = M::COMPACT_LAYOUT;
  const int automatic = M::AUTOMATIC_INTEGRATION;
  ours("compute default", automatic, compact, 0, 256, 0);
  if (o.TransferFunction != "ramp")
  {
    ours("compute no-skipping", automatic, compact, 0, 256, 0, 4, false);
  }
  if (o.Rate > 0)
  {
    std::ostringstream name;
    name << "compute interactive " << o.Rate << "/s";
    ours(name.str(), automatic, compact, 0, 256, 0);
    settings.back().Rate = o.Rate;
  }
  ours("compute partial compact", partial, compact, 0, 256, 0);
  if (o.OursOnly)
  {
    return settings;
  }
  ours("fragment default", automatic, compact, 0, 256, 0);
  if (o.Sweep != "pipelines")
  {
    ours("compute partial paper", partial, M::PAPER_LAYOUT, 0, 256, 0);
    ours("compute table3d compact", M::PRE_INTEGRATION_3D, compact, 0, 256, 0);
    ours("compute table2d compact", M::PRE_INTEGRATION_2D, compact, 0, 256, 0);
    ours("fragment partial compact N16 T256", partial, compact, 16, 256, 0);
    ours("fragment partial paper N0 T256", partial, M::PAPER_LAYOUT, 0, 256, 0);
  }
  if (o.Sweep == "full")
  {
    ours("fragment partial compact N0 T64", partial, compact, 0, 64, 0);
    ours("fragment partial compact N0 T128", partial, compact, 0, 128, 0);
    ours("fragment table3d compact N0 T256", M::PRE_INTEGRATION_3D, compact, 0, 256, 0);
    ours("fragment table2d compact N0 T256", M::PRE_INTEGRATION_2D, compact, 0, 256, 0);
    ours("fragment partial compact N4 T256", partial, compact, 4, 256, 0);
    ours("fragment partial compact N64 T256", partial, compact, 64, 256, 0);
    ours("compute table3d64 compact", M::PRE_INTEGRATION_3D, compact, 0, 256, 64);
    ours("compute table2d64 compact", M::PRE_INTEGRATION_2D, compact, 0, 256, 64);
  }
  return settings;
}

// What ParaView users do instead: resample `grid` to a regular grid of r^3 points (points
// outside the mesh are masked out) for VTK's GPU ray caster; `prepareMs` gets the resampling's
// time.
vtkSmartPointer<vtkAbstractVolumeMapper> ResampledGPUMapper(
  vtkUnstructuredGrid* grid, int r, double& prepareMs)
{
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  vtkNew<vtkResampleToImage> resample;
  resample->SetInputDataObject(grid);
  resample->SetSamplingDimensions(r, r, r);
  resample->UseInputBoundsOn();
  resample->Update();
  timer->StopTimer();
  prepareMs = 1000.0 * timer->GetElapsedTime();
  vtkImageData* image = resample->GetOutput();
  auto volumeImage = vtkSmartPointer<vtkImageData>::New();
  volumeImage->ShallowCopy(image);
  auto mask = vtkSmartPointer<vtkImageData>::New();
  mask->CopyStructure(image);
  vtkDataArray* valid = image->GetPointData()->GetArray(resample->GetMaskArrayName());
  vtkNew<vtkUnsignedCharArray> maskValues;
  maskValues->SetNumberOfTuples(valid->GetNumberOfTuples());
  for (vtkIdType i = 0; i < valid->GetNumberOfTuples(); ++i)
  {
    maskValues->SetValue(i, valid->GetTuple1(i) != 0 ? 255 : 0);
  }
  mask->GetPointData()->SetScalars(maskValues);
  auto m = vtkSmartPointer<vtkGPUVolumeRayCastMapper>::New();
  m->SetInputData(volumeImage);
  m->SetMaskInput(mask);
  m->SetMaskTypeToBinary();
  m->AutoAdjustSampleDistancesOff();
  double spacing[3];
  volumeImage->GetSpacing(spacing);
  m->SetSampleDistance(0.5 * std::min({ spacing[0], spacing[1], spacing[2] }));
  // The mask and image are kept alive by the mapper.
  return m;
}

// VTK's mappers, as --no-others, --pt-only, --zsweep-max-tets and --resample say: the projected
// tetrahedra, Bunyk's ray caster with partial pre-integration (TiledRayCastSharedScenes.h),
// ZSweep up to 512 px, resampling for the GPU ray caster.
void AddOtherMappers(
  std::vector<Setting>& settings, vtkUnstructuredGrid* grid, const Options& o, int size)
{
  settings.push_back({ "projected_tetrahedra", "default",
    [=](double&)
    {
      auto m = vtkSmartPointer<vtkProjectedTetrahedraMapper>::New();
      m->SetInputData(grid);
      return vtkSmartPointer<vtkAbstractVolumeMapper>(m);
    } });
  if (o.ProjectedTetrahedraOnly)
  {
    return;
  }
  settings.push_back({ "bunyk_raycast", "partial preintegration",
    [=](double&)
    { return vtkSmartPointer<vtkAbstractVolumeMapper>(trcscene::MakeBunykMapper(grid)); } });
  if (grid->GetNumberOfCells() <= o.ZSweepMaxTets && size <= 512)
  {
    settings.push_back({ "zsweep", "default",
      [=](double&)
      {
        auto m = vtkSmartPointer<vtkUnstructuredGridVolumeZSweepMapper>::New();
        m->SetInputData(grid);
        m->AutoAdjustSampleDistancesOff();
        m->SetImageSampleDistance(1.0f);
        return vtkSmartPointer<vtkAbstractVolumeMapper>(m);
      } });
  }
  for (int r : o.Resample)
  {
    settings.push_back({ "resample_gpu", "res" + std::to_string(r),
      [=](double& prepareMs) { return ResampledGPUMapper(grid, r, prepareMs); } });
  }
}

// Every setting timed on `grid` at `size` pixels, in the order of the CSV rows.
std::vector<Setting> MakeSettings(vtkUnstructuredGrid* grid, const Options& o, int size)
{
  if (o.Sweep == "defaults")
  {
    return DefaultsSweep(grid);
  }
  std::vector<Setting> settings = OurSettings(grid, o);
  if (!o.OursOnly && o.Others)
  {
    AddOtherMappers(settings, grid, o, size);
  }
  return settings;
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
        o.Sweep != "pipelines")
      {
        std::cerr << "--sweep takes quick, full, defaults or pipelines\n";
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

  // First frame: everything the mapper prepares.
  SetView(renderer, grid, 0, o.Frames);
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  window->Render();
  window->WaitForCompletion();
  timer->StopTimer();
  row.FirstFrameMs = 1000.0 * timer->GetElapsedTime();

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
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    vtkSmartPointer<vtkUnstructuredGrid> ordered = ReorderMesh(reader->GetOutput(), o.Order);
    vtkUnstructuredGrid* grid = ordered;
    if (grid->GetNumberOfCells() == 0 || !grid->GetPointData()->GetScalars())
    {
      std::cerr << path << ": no cells or no point scalars; skipped\n";
      continue;
    }
    std::string mesh = path.substr(path.find_last_of('/') + 1);
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
