/*=========================================================================

  Program:   TiledRayCast
  Module:    TiledRayCastSharedScenes.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The scenes the tests and the benchmarks share, so that a figure of docs/benchmarks.md and the
// test that bounds it are about the same transfer function: the ramp of the mapper's scenes
// (TiledRayCastTestScene.h, BenchmarkMappers) and the scene of the comparison with VTK's Bunyk
// ray caster (TestTetReferenceRendererBunyk, BenchmarkReferenceRenderer). Plain VTK, no test
// driver: the benchmarks include it too (Benchmarks/CMakeLists.txt).
#ifndef TiledRayCastSharedScenes_h
#define TiledRayCastSharedScenes_h

#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGridPartialPreIntegration.h"
#include "vtkUnstructuredGridVolumeRayCastMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cmath>

namespace trcscene
{
// A property of these transfer functions (the first component's) and unit distance: what every
// scene's transfer function ends in.
inline vtkSmartPointer<vtkVolumeProperty> MakeVolumeProperty(
  vtkColorTransferFunction* color, vtkPiecewiseFunction* opacity, double unitDistance)
{
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(unitDistance);
  return property;
}

// The ramp of the mapper's scenes: a transfer function over [lo, hi] with a few nodes, varied
// colour and a moderate opacity; the unit distance is a fraction of the mesh's size so that rays
// neither vanish nor saturate.
inline vtkSmartPointer<vtkVolumeProperty> MakeProperty(
  double lo, double hi, double unitDistance, bool narrowFeature = false)
{
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(lo, 0.1, 0.3, 1.0);
  color->AddRGBPoint(lo + 0.4 * (hi - lo), 0.2, 0.9, 0.4);
  color->AddRGBPoint(lo + 0.7 * (hi - lo), 1.0, 0.9, 0.1);
  color->AddRGBPoint(hi, 1.0, 0.2, 0.1);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(lo, 0.05);
  opacity->AddPoint(lo + 0.5 * (hi - lo), 0.3);
  if (narrowFeature)
  {
    // A spike 4 % of the range wide: what vertex-classified mappers get wrong.
    opacity->AddPoint(lo + 0.78 * (hi - lo), 0.3);
    opacity->AddPoint(lo + 0.80 * (hi - lo), 1.0);
    opacity->AddPoint(lo + 0.82 * (hi - lo), 0.3);
  }
  opacity->AddPoint(hi, 0.6);
  return MakeVolumeProperty(color, opacity, unitDistance);
}

// The ramp over a grid's active point scalars ([0, 1] without), with a unit distance of a
// fraction of its bounding box diagonal.
inline vtkSmartPointer<vtkVolumeProperty> MakePropertyFor(
  vtkDataSet* grid, double fraction = 0.05, bool narrowFeature = false)
{
  double range[2] = { 0, 1 };
  if (grid->GetPointData()->GetScalars())
  {
    grid->GetPointData()->GetScalars()->GetRange(range);
  }
  return MakeProperty(range[0], range[1], fraction * grid->GetLength(), narrowFeature);
}

// Opacity only over [lo + at w, lo + (at + width) w] of the range [lo, lo + w]: zero at both
// ends of that band and 1 in its middle, zero elsewhere (how people explore CFD data, and what
// empty-space skipping is for); the ramp's colours over the whole range.
inline vtkSmartPointer<vtkVolumeProperty> MakeBandProperty(
  const double range[2], double at, double width, double unitDistance)
{
  const double w = range[1] - range[0];
  const double a = range[0] + at * w;
  const double b = a + width * w;
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(range[0], 0.1, 0.3, 1.0);
  color->AddRGBPoint(range[0] + 0.4 * w, 0.2, 0.9, 0.4);
  color->AddRGBPoint(range[0] + 0.7 * w, 1.0, 0.9, 0.1);
  color->AddRGBPoint(range[1], 1.0, 0.2, 0.1);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(range[0], 0.0);
  opacity->AddPoint(a, 0.0);
  opacity->AddPoint(0.5 * (a + b), 1.0);
  opacity->AddPoint(b, 0.0);
  opacity->AddPoint(range[1], 0.0);
  return MakeVolumeProperty(color, opacity, unitDistance);
}

// The length of the diagonal of `bounds` (xmin, xmax, ymin, ...).
inline double Diagonal(const double bounds[6])
{
  return std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
}

// The transfer function of the comparison with Bunyk: a three-node colour ramp and an opacity
// ramp (0.05 to 0.9) over the scalar range, unit distance = diagonal / 15. The nodes sit at the
// ends of the range on purpose: Bunyk's partial pre-integration only splits segments at colour
// nodes (and the first opacity node), so the opacity is a single ramp across the range.
// `midpoint` and `sharpness` go to every node but the last opacity one (the benchmark's
// --tf sharpness; 0.5 and 0 are VTK's defaults); the colour space is the caller's to set.
inline vtkSmartPointer<vtkVolumeProperty> MakeBunykProperty(
  const double range[2], double diagonal, double midpoint = 0.5, double sharpness = 0.0)
{
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(range[0], 0.1, 0.2, 1.0, midpoint, sharpness);
  color->AddRGBPoint(0.5 * (range[0] + range[1]), 0.2, 1.0, 0.3, midpoint, sharpness);
  color->AddRGBPoint(range[1], 1.0, 0.3, 0.1, midpoint, sharpness);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(range[0], 0.05, midpoint, sharpness);
  opacity->AddPoint(range[1], 0.9);
  return MakeVolumeProperty(color, opacity, diagonal / 15.0);
}

// `grid` in VTK's vtkUnstructuredGridVolumeRayCastMapper with partial pre-integration (the
// reference's optical model), one ray per pixel.
inline vtkSmartPointer<vtkUnstructuredGridVolumeRayCastMapper> MakeBunykMapper(vtkDataSet* grid)
{
  auto mapper = vtkSmartPointer<vtkUnstructuredGridVolumeRayCastMapper>::New();
  mapper->SetInputData(grid);
  vtkNew<vtkUnstructuredGridPartialPreIntegration> integrator;
  mapper->SetRayIntegrator(integrator);
  mapper->SetImageSampleDistance(1.0f);
  mapper->AutoAdjustSampleDistancesOff();
  return mapper;
}

// MakeBunykMapper's mapper of `grid` in a volume of `property`.
inline vtkSmartPointer<vtkVolume> MakeBunykVolume(vtkDataSet* grid, vtkVolumeProperty* property)
{
  auto volume = vtkSmartPointer<vtkVolume>::New();
  volume->SetMapper(MakeBunykMapper(grid));
  volume->SetProperty(property);
  return volume;
}
}

#endif
