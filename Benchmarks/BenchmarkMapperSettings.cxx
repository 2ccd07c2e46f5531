/*=========================================================================

  Program:   TiledRayCast
  Module:    BenchmarkMapperSettings.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "BenchmarkMapperSettings.h"

#include "TiledRayCastSharedScenes.h"
#include "vtkDataArray.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkProjectedTetrahedraMapper.h"
#include "vtkResampleToImage.h"
#include "vtkTiledRayCastVolumeMapper.h"
#include "vtkTimerLog.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridVolumeRayCastMapper.h"
#include "vtkUnstructuredGridVolumeZSweepMapper.h"

#include <algorithm>
#include <sstream>

using trcmappers::Options;
using trcmappers::Setting;

namespace
{
using M = vtkTiledRayCastVolumeMapper;

// Our mapper of `grid` in the pipeline that `name` starts with ("compute ...": the compute
// pipeline, any other the fragment pipeline), with these settings; `table` > 0 sets the tables'
// scalar size (and half of it as their length size).
Setting Ours(vtkUnstructuredGrid* grid, const std::string& name, int mode, int layout, int n,
  int tile, int table, int queryInterval = 4, bool skipping = true, vtkIdType bufferTexels = 0)
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
      m->SetMaximumTextureBufferSize(bufferTexels);
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
  if (o.Sweep == "default")
  {
    return settings; // the dataset ladder's largest rungs
  }
  if (o.Sweep == "buffers")
  {
    // The mesh split over texture buffers as meshes above the GPU's largest texture buffer are
    // (134M tetrahedra on NVIDIA's): buffers of the least power of two texels that is at least
    // a quarter (then an eighth) of the tetrahedra, 3 to 4 (5 to 8) buffers per array.
    for (int parts : { 4, 8 })
    {
      vtkIdType texels = 1;
      while (texels * parts < grid->GetNumberOfCells())
      {
        texels *= 2;
      }
      settings.push_back(Ours(grid, "compute buffers T/" + std::to_string(parts), automatic,
        compact, 0, 256, 0, 4, true, texels));
    }
    return settings;
  }
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

}

//------------------------------------------------------------------------------
std::vector<Setting> trcmappers::MakeSettings(vtkUnstructuredGrid* grid, const Options& o, int size)
{
  if (o.Sweep == "defaults")
  {
    return DefaultsSweep(grid);
  }
  std::vector<Setting> settings = OurSettings(grid, o);
  if (!o.OursOnly && o.Others && o.Sweep != "default" && o.Sweep != "buffers")
  {
    AddOtherMappers(settings, grid, o, size);
  }
  return settings;
}
