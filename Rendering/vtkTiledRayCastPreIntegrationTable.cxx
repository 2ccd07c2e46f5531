/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastPreIntegrationTable.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastPreIntegrationTable.h"

#include "vtkColorTransferFunction.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkSMPTools.h"
#include "vtkTetRayIntegrator.h"
#include "vtkTimerLog.h"
#include "vtkTiledRayCastTransferFunction.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>

namespace
{
// Entries' optical depth per unit length at most this: any segment longer than 1e-28 world
// units is then opaque (alpha = 1 - exp(-80) and beyond), and the texture holds no infinity
// (which trilinear filtering would turn into NaN next to a zero weight).
constexpr double MaximumExtinction = 1e30;

// The optical depth per unit length of segments from sf to sb, from lengths below `length`
// until the integrator gives a finite depth: for a medium so opaque that even the table's
// lengths reach its cut-off. MaximumExtinction where no length does (an opacity of 1).
double OpticalDepthPerLength(vtkTetRayIntegrator* integrator, double sf, double sb, double length)
{
  double rgba[4];
  for (double probe = length > 0.0 ? length * 1e-3 : 1.0; probe > 1e-290; probe *= 1e-3)
  {
    double depth = 0.0;
    integrator->IntegrateWithDepth(sf, sb, probe, rgba, &depth);
    if (std::isfinite(depth))
    {
      return std::min(depth / probe, MaximumExtinction);
    }
  }
  return MaximumExtinction;
}
}

vtkStandardNewMacro(vtkTiledRayCastPreIntegrationTable);

//------------------------------------------------------------------------------
vtkTiledRayCastPreIntegrationTable::vtkTiledRayCastPreIntegrationTable() = default;

//------------------------------------------------------------------------------
vtkTiledRayCastPreIntegrationTable::~vtkTiledRayCastPreIntegrationTable() = default;

//------------------------------------------------------------------------------
bool vtkTiledRayCastPreIntegrationTable::Update(vtkVolumeProperty* property,
  vtkTiledRayCastTransferFunction* transferFunction, const double scalarRange[2])
{
  if (!property || !transferFunction)
  {
    vtkErrorMacro("No volume property or transfer function.");
    return false;
  }
  // The node list changes whenever the property's functions or the scalar range change.
  const vtkMTimeType source = std::max(transferFunction->GetMTime(), property->GetMTime());
  int size[3];
  const double width = scalarRange[1] - scalarRange[0];
  const int cap = std::min(this->Dimension == 3 ? 256 : 1024, this->MaximumSize);
  if (this->RequestedScalarSize > 0)
  {
    size[0] = std::min(this->RequestedScalarSize, this->MaximumSize);
  }
  else
  {
    const double feature = transferFunction->GetNarrowestFeature();
    const double wanted = width > 0 && feature > 0 ? 2.0 * width / feature + 1.0 : 2.0;
    size[0] = static_cast<int>(std::min<double>(cap, std::max(32.0, std::ceil(wanted))));
  }
  size[0] = std::max(size[0], 2);
  size[1] = size[0];
  size[2] = this->Dimension == 3
    ? std::max(2,
        std::min(this->RequestedLengthSize > 0 ? this->RequestedLengthSize : 64, this->MaximumSize))
    : 1;
  if (this->BuiltFrom == source && this->BuiltTime >= this->GetMTime() &&
    std::equal(size, size + 3, this->Planned) && this->Range[0] == scalarRange[0] &&
    this->Range[1] == scalarRange[1] && !this->Table.empty())
  {
    return true;
  }

  vtkNew<vtkTetRayIntegrator> integrator;
  if (!integrator->Initialize(property))
  {
    vtkErrorMacro("Cannot integrate the volume property's transfer functions.");
    return false;
  }
  const double maxLength = this->MaximumLength;
  const double reference = this->ReferenceLength;
  const bool is3D = this->Dimension == 3;
  std::copy(size, size + 3, this->Planned);
  this->ReducedFromScalarSize = 0;
  const int fitted = this->FitBudget(integrator, size, scalarRange);
  if (fitted < size[0])
  {
    this->ReducedFromScalarSize = size[0];
    size[0] = size[1] = fitted;
  }
  std::copy(size, size + 3, this->Size);
  this->Range[0] = scalarRange[0];
  this->Range[1] = scalarRange[1];
  const int n = size[0];
  const int nl = size[2];
  this->Table.assign(static_cast<size_t>(n) * n * nl * 4, 0.0f);
  float* table = this->Table.data();
  const double lo = scalarRange[0];
  // One (front, back) row of lengths per work item.
  // Only the getter of the property's own colour function: the other one would create a default
  // function and switch the property's colour channels to it.
  const bool gray = property->GetColorChannels(0) == 1;
  vtkPiecewiseFunction* grays = gray ? property->GetGrayTransferFunction(0) : nullptr;
  vtkColorTransferFunction* colors = gray ? nullptr : property->GetRGBTransferFunction(0);
  // The mean colour of segments too short for their alpha to tell it: taken at a length so
  // short that attenuation inside the segment is negligible, else (no opacity at all) the colour
  // function at the middle of the scalars.
  const double shortLength = 1e-6 * std::max(is3D ? maxLength : reference, 1e-300);
  auto shortMeanColor = [&](double sf, double sb, double mean[3])
  {
    double rgba[4];
    integrator->Integrate(sf, sb, shortLength, rgba);
    if (rgba[3] > 0)
    {
      for (int c = 0; c < 3; ++c)
      {
        mean[c] = rgba[c] / rgba[3];
      }
      return;
    }
    const double middle = 0.5 * (sf + sb);
    if (grays)
    {
      mean[0] = mean[1] = mean[2] = grays->GetValue(middle);
    }
    else if (colors)
    {
      colors->GetColor(middle, mean);
    }
    else
    {
      mean[0] = mean[1] = mean[2] = 0.0;
    }
  };
  vtkSMPTools::For(0, static_cast<vtkIdType>(n) * n,
    [&](vtkIdType begin, vtkIdType end)
    {
      double rgba[4];
      for (vtkIdType fb = begin; fb < end; ++fb)
      {
        const int front = static_cast<int>(fb % n);
        const int back = static_cast<int>(fb / n);
        const double sf = lo + width * front / (n - 1);
        const double sb = lo + width * back / (n - 1);
        double shortMean[3];
        bool haveShortMean = false;
        // The optical depth per unit length of the segments from sf to sb, the same at every
        // length (D = L Int_0^1 tau(sf + (sb - sf) u) du): from the first length whose depth
        // the integrator gives (it says +inf past its cut-off, where alpha is 1 in double).
        double extinction = -1.0;
        for (int l = 0; l < nl; ++l)
        {
          const double length = is3D ? maxLength * l / (nl - 1) : reference;
          double depth = 0.0;
          integrator->IntegrateWithDepth(sf, sb, length, rgba, &depth);
          if (extinction < 0.0 && length > 0.0 && std::isfinite(depth))
          {
            extinction = std::min(depth / length, MaximumExtinction);
          }
          float* entry = table + 4 * ((static_cast<size_t>(l) * n + back) * n + front);
          // Relative to the colour's own rounding: below this alpha the mean colour is the
          // short-segment limit (alpha 0 at length 0, or no opacity at all).
          if (rgba[3] > 1e-12)
          {
            for (int c = 0; c < 3; ++c)
            {
              entry[c] = static_cast<float>(rgba[c] / rgba[3]);
            }
          }
          else
          {
            if (!haveShortMean)
            {
              shortMeanColor(sf, sb, shortMean);
              haveShortMean = true;
            }
            for (int c = 0; c < 3; ++c)
            {
              entry[c] = static_cast<float>(shortMean[c]);
            }
          }
        }
        if (extinction < 0.0)
        {
          extinction = OpticalDepthPerLength(integrator, sf, sb, is3D ? maxLength : reference);
        }
        for (int l = 0; l < nl; ++l)
        {
          table[4 * ((static_cast<size_t>(l) * n + back) * n + front) + 3] =
            static_cast<float>(extinction);
        }
      }
    });
  this->BuiltFrom = source;
  this->Modified();
  this->BuiltTime = this->GetMTime();
  return true;
}

//------------------------------------------------------------------------------
int vtkTiledRayCastPreIntegrationTable::FitBudget(
  vtkTetRayIntegrator* integrator, const int size[3], const double scalarRange[2]) const
{
  // Time every length of a few (front, back) pairs spread over the grid, project to the whole
  // table on the threads the build will use, and shrink the scalar axes (their square) to fit.
  const int n = size[0];
  const int nl = size[2];
  const vtkIdType pairs = static_cast<vtkIdType>(n) * n;
  const vtkIdType samples = std::min<vtkIdType>(pairs, 48);
  const double width = scalarRange[1] - scalarRange[0];
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  double rgba[4];
  for (vtkIdType k = 0; k < samples; ++k)
  {
    // A spread of fronts and backs: (k * 7919) mod n against k * n / samples.
    const int front = static_cast<int>((k * 7919) % n);
    const int back = static_cast<int>(k * n / samples);
    const double sf = scalarRange[0] + width * front / (n - 1);
    const double sb = scalarRange[0] + width * back / (n - 1);
    for (int l = 0; l < nl; ++l)
    {
      const double length =
        this->Dimension == 3 ? this->MaximumLength * l / (nl - 1) : this->ReferenceLength;
      integrator->Integrate(sf, sb, length, rgba);
    }
  }
  timer->StopTimer();
  const int threads = std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads());
  const double projected = timer->GetElapsedTime() * pairs / samples / threads;
  if (projected <= this->BuildTimeBudget || n <= 32)
  {
    return n;
  }
  return std::max(32, static_cast<int>(n * std::sqrt(this->BuildTimeBudget / projected)));
}

//------------------------------------------------------------------------------
void vtkTiledRayCastPreIntegrationTable::GetSize(int size[3]) const
{
  std::copy(this->Size, this->Size + 3, size);
}

//------------------------------------------------------------------------------
void vtkTiledRayCastPreIntegrationTable::GetScalarRange(double range[2]) const
{
  range[0] = this->Range[0];
  range[1] = this->Range[1];
}

//------------------------------------------------------------------------------
void vtkTiledRayCastPreIntegrationTable::GetEntry(
  int front, int back, int length, double rgba[4]) const
{
  const int n = this->Size[0];
  if (front < 0 || back < 0 || length < 0 || front >= n || back >= n || length >= this->Size[2])
  {
    rgba[0] = rgba[1] = rgba[2] = rgba[3] = 0.0;
    return;
  }
  const float* entry =
    this->Table.data() + 4 * ((static_cast<size_t>(length) * n + back) * n + front);
  for (int c = 0; c < 4; ++c)
  {
    rgba[c] = entry[c];
  }
}

//------------------------------------------------------------------------------
void vtkTiledRayCastPreIntegrationTable::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Dimension: " << this->Dimension << "\n";
  os << indent << "Size: " << this->Size[0] << " " << this->Size[1] << " " << this->Size[2] << "\n";
  os << indent << "ScalarRange: " << this->Range[0] << " " << this->Range[1] << "\n";
  os << indent << "MaximumLength: " << this->MaximumLength << "\n";
  os << indent << "ReferenceLength: " << this->ReferenceLength << "\n";
  os << indent << "BuildTimeBudget: " << this->BuildTimeBudget << " s\n";
  os << indent << "ReducedFromScalarSize: " << this->ReducedFromScalarSize << "\n";
  os << indent << "RequestedScalarSize: " << this->RequestedScalarSize << "\n";
  os << indent << "RequestedLengthSize: " << this->RequestedLengthSize << "\n";
}
