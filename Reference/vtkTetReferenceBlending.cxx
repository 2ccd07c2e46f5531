/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetReferenceBlending.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetReferenceBlending.h"

#include "vtkColorTransferFunction.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolumeMapper.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>

namespace
{
// s normalised to the data's scalar range (0 where the range is a single value).
double Normalised(const double range[2], double s)
{
  const double width = range[1] - range[0];
  return width > 0 ? (s - range[0]) / width : 0.0;
}

// The integral over scalars [lo, hi] of opacity(s) times s normalised to the data's range.
double WeightedIntegral(
  vtkPiecewiseFunction* opacity, const double range[2], double lo, double hi)
{
  std::vector<double> cuts = { lo };
  for (int i = 0; i < opacity->GetSize(); ++i)
  {
    double node[4];
    opacity->GetNodeValue(i, node);
    if (node[0] > lo && node[0] < hi)
    {
      cuts.push_back(node[0]);
    }
  }
  cuts.push_back(hi);
  // 3-point Gauss-Legendre on [-1, 1].
  const double x[3] = { -std::sqrt(0.6), 0.0, std::sqrt(0.6) };
  const double w[3] = { 5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0 };
  double sum = 0.0;
  for (size_t k = 0; k + 1 < cuts.size(); ++k)
  {
    const int parts = 8;
    const double step = (cuts[k + 1] - cuts[k]) / parts;
    for (int p = 0; p < parts; ++p)
    {
      const double mid = cuts[k] + (p + 0.5) * step;
      for (int q = 0; q < 3; ++q)
      {
        const double s = mid + 0.5 * step * x[q];
        sum += 0.5 * step * w[q] * opacity->GetValue(s) * Normalised(range, s);
      }
    }
  }
  return sum;
}
}

//------------------------------------------------------------------------------
void vtkTetReferenceBlending::BlendRay(const std::vector<vtkTetReferenceRayCaster::Hit>& hits,
  const std::vector<unsigned char>& transparent, const Settings& settings, double unitLength,
  double rgba[4])
{
  rgba[0] = rgba[1] = rgba[2] = rgba[3] = 0.0;
  vtkVolumeProperty* property = settings.Property;
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  const int mode = settings.Mode;
  const bool extreme = mode == vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND ||
    mode == vtkVolumeMapper::MINIMUM_INTENSITY_BLEND;
  bool seen = false;
  double best = 0.0;
  double integral = 0.0;
  double length = 0.0;
  for (const vtkTetReferenceRayCaster::Hit& hit : hits)
  {
    const double d = (hit.Z1 - hit.Z0) * unitLength;
    if (transparent[hit.Tet] || !(d > 0.0))
    {
      continue;
    }
    const double lo = std::min(hit.S0, hit.S1);
    const double hi = std::max(hit.S0, hit.S1);
    if (extreme)
    {
      const double value = mode == vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND ? hi : lo;
      const bool better =
        mode == vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND ? value > best : value < best;
      best = !seen || better ? value : best;
      seen = true;
      continue;
    }
    seen = true;
    double from = lo, to = hi, part = d;
    if (mode == vtkVolumeMapper::AVERAGE_INTENSITY_BLEND)
    {
      from = std::max(lo, settings.AverageRange[0]);
      to = std::min(hi, settings.AverageRange[1]);
      if (to < from || (to == from && hi > lo))
      {
        continue;
      }
      part = hi > lo ? d * (to - from) / (hi - lo) : d;
    }
    integral += to > from
      ? WeightedIntegral(opacity, settings.ScalarRange, from, to) * part / (to - from)
      : opacity->GetValue(from) * Normalised(settings.ScalarRange, from) * part;
    length += part;
  }
  if (!seen)
  {
    return;
  }
  if (extreme)
  {
    double color[3] = { 0.0, 0.0, 0.0 };
    if (property->GetColorChannels(0) == 1)
    {
      color[0] = color[1] = color[2] = property->GetGrayTransferFunction(0)->GetValue(best);
    }
    else
    {
      property->GetRGBTransferFunction(0)->GetColor(best, color);
    }
    const double alpha = std::min(std::max(opacity->GetValue(best), 0.0), 1.0);
    rgba[0] = color[0] * alpha;
    rgba[1] = color[1] * alpha;
    rgba[2] = color[2] * alpha;
    rgba[3] = alpha;
    return;
  }
  double gray = 0.0;
  if (mode == vtkVolumeMapper::AVERAGE_INTENSITY_BLEND)
  {
    if (!(length > 0.0))
    {
      return;
    }
    gray = integral / length;
  }
  else
  {
    gray = integral / property->GetScalarOpacityUnitDistance(0);
  }
  gray = std::min(std::max(gray, 0.0), 1.0);
  rgba[0] = rgba[1] = rgba[2] = gray;
  rgba[3] = 1.0;
}
