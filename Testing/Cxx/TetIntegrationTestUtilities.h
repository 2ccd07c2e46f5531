/*=========================================================================

  Program:   TiledRayCast
  Module:    TetIntegrationTestUtilities.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Helpers shared by the tests of the exact integrator (TiledRayCast::Integration) and of the
// reference renderer (TiledRayCast::Reference): a constant transfer function and a brute-force
// integrator of the optical model. They use neither the integrator's nor the renderer's code:
// the tests compare two independent computations.
#ifndef TetIntegrationTestUtilities_h
#define TetIntegrationTestUtilities_h

#include "TiledRayCastTestCheck.h" // For TRC_CHECK

#include "vtkColorTransferFunction.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkSmartPointer.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>

// Checks |value - expected| <= bound and prints both on failure.
#define TRC_CHECK_NEAR(value, expected, bound)                                                     \
  do                                                                                               \
  {                                                                                                \
    const double trcValue = (value), trcExpected = (expected);                                     \
    if (!(std::fabs(trcValue - trcExpected) <= (bound)))                                           \
    {                                                                                              \
      std::cerr << __FILE__ << ":" << __LINE__ << ": " #value " = " << trcValue << ", expected "   \
                << trcExpected << " within " << (bound) << " (difference "                         \
                << std::fabs(trcValue - trcExpected) << ")" << std::endl;                          \
      return EXIT_FAILURE;                                                                         \
    }                                                                                              \
  } while (false)

namespace trc
{

// A property with constant colour c and constant attenuation tau (unit distance 1).
inline vtkSmartPointer<vtkVolumeProperty> ConstantProperty(double tau, const double c[3])
{
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(-1.0, c[0], c[1], c[2]);
  color->AddRGBPoint(1e6, c[0], c[1], c[2]);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(-1.0, tau);
  opacity->AddPoint(1e6, tau);
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(1.0);
  return property;
}

// Brute force: march a segment of length len (scalar s(t), t in [0, len]) in n equal steps,
// each with the transfer functions evaluated by VTK at its midpoint and integrated exactly as
// a constant step. Error O(step^2) for smooth functions, O(step) at jumps.
inline void BruteForce(vtkVolumeProperty* property, const std::function<double(double)>& s,
  double len, int n, double rgba[4])
{
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  vtkColorTransferFunction* color =
    property->GetColorChannels(0) == 1 ? nullptr : property->GetRGBTransferFunction(0);
  vtkPiecewiseFunction* gray = color ? nullptr : property->GetGrayTransferFunction(0);
  const double unit = property->GetScalarOpacityUnitDistance(0);
  const double h = len / n;
  double transmittance = 1.0, c[3] = { 0.0, 0.0, 0.0 };
  for (int k = 0; k < n; ++k)
  {
    const double sv = s((k + 0.5) * h);
    const double tau = std::max(0.0, opacity->GetValue(sv)) / unit;
    double rgb[3];
    if (color)
    {
      color->GetColor(sv, rgb);
    }
    else
    {
      rgb[0] = rgb[1] = rgb[2] = gray->GetValue(sv);
    }
    const double a = -std::expm1(-tau * h);
    for (int q = 0; q < 3; ++q)
    {
      c[q] += transmittance * a * rgb[q];
    }
    transmittance *= 1.0 - a;
  }
  rgba[0] = c[0];
  rgba[1] = c[1];
  rgba[2] = c[2];
  rgba[3] = 1.0 - transmittance;
}

} // namespace trc

#endif
