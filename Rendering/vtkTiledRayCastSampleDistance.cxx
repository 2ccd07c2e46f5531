/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastSampleDistance.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastSampleDistance.h"

#include <algorithm>
#include <cmath>

//------------------------------------------------------------------------------
double vtkTiledRayCastSampleDistance::Choose(
  bool adjust, double fixed, double minimum, double maximum, double allocatedSeconds) const
{
  if (!adjust)
  {
    return std::max(1.0, fixed);
  }
  const double lo = std::max(1.0, std::min(minimum, maximum));
  const double hi = std::max(lo, std::max(minimum, maximum));
  if (this->FullFrameSeconds <= 0.0 || !(allocatedSeconds > 0.0))
  {
    return lo;
  }
  // t(d) = t(1) / d^2: the distance at which the frame takes the allocated time.
  const double fitted = std::sqrt(this->FullFrameSeconds / allocatedSeconds);
  return std::min(hi, std::max(lo, fitted));
}

//------------------------------------------------------------------------------
void vtkTiledRayCastSampleDistance::Measured(double distance, double seconds)
{
  if (!(seconds > 0.0) || !(distance >= 1.0))
  {
    return;
  }
  const double full = seconds * distance * distance;
  this->FullFrameSeconds =
    this->FullFrameSeconds > 0.0 ? 0.5 * (this->FullFrameSeconds + full) : full;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastSampleDistance::ComputeImageSize(
  int width, int height, double distance, int size[2])
{
  const double d = std::max(1.0, distance);
  size[0] = std::max(1, static_cast<int>(std::ceil(width / d - 1e-9)));
  size[1] = std::max(1, static_cast<int>(std::ceil(height / d - 1e-9)));
}
