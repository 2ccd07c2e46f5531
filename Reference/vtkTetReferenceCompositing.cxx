/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetReferenceCompositing.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkTetReferenceRenderer's public image helpers are defined here too, with the compositing
// along a ray: the compositing of the renderer's output over a background is this file's concern.
#include "vtkTetReferenceCompositing.h"
#include "vtkTetReferenceRenderer.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkTetRayIntegrator.h"
#include "vtkTetReferenceShading.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace
{
// A ray stops once its transmittance is below this: what lies behind changes no value by more.
constexpr double TerminationDepth = 36.0; // exp(-36) = 2.3e-16
}

//------------------------------------------------------------------------------
void vtkTetReferenceCompositing::CompositeRay(
  const std::vector<vtkTetReferenceRayCaster::Hit>& hits,
  const std::vector<unsigned char>& transparent, vtkTetRayIntegrator* integrator, double unitLength,
  double rgba[4], const vtkTetReferenceShading* shading, const double d[3])
{
  const bool shaded = shading && shading->GetEnabled() && d;
  const bool gradientOpacity = shading && shading->GetGradientOpacityEnabled();
  double color[3] = { 0.0, 0.0, 0.0 };
  double opticalDepth = 0.0;
  for (const vtkTetReferenceRayCaster::Hit& hit : hits)
  {
    if (transparent[hit.Tet])
    {
      continue;
    }
    double segment[4], segmentDepth;
    // Gradient opacity scales the attenuation, constant over the segment: its length.
    const double scale = gradientOpacity ? shading->OpacityScale(hit.Tet) : 1.0;
    integrator->IntegrateWithDepth(
      hit.S0, hit.S1, (hit.Z1 - hit.Z0) * unitLength * scale, segment, &segmentDepth);
    if (shaded)
    {
      shading->Apply(hit.Tet, d, -std::expm1(-segmentDepth), segment);
    }
    const double transmittance = std::exp(-opticalDepth);
    for (int k = 0; k < 3; ++k)
    {
      color[k] += transmittance * segment[k];
    }
    opticalDepth += segmentDepth;
    if (opticalDepth > TerminationDepth)
    {
      break;
    }
  }
  rgba[0] = color[0];
  rgba[1] = color[1];
  rgba[2] = color[2];
  rgba[3] = -std::expm1(-opticalDepth);
}

namespace
{
// The premultiplied RGBA scalars of `rgba`; null, with a warning naming the caller, when there are
// none or there is no output image.
vtkDataArray* RGBAScalars(const char* caller, vtkImageData* rgba, vtkImageData* output)
{
  vtkDataArray* in = rgba ? rgba->GetPointData()->GetScalars() : nullptr;
  if (!in || in->GetNumberOfComponents() != 4 || !output)
  {
    vtkGenericWarningMacro(<< caller << " needs an image with 4-component scalars.");
    return nullptr;
  }
  return in;
}

// `rgba` composited over `background` into `output`: 3-component "RGB" scalars of ArrayT, each
// composited value stored as convert(value).
template <typename ArrayT, typename Convert>
void CompositeInto(const char* caller, vtkImageData* rgba, const double background[3],
  vtkImageData* output, Convert convert)
{
  vtkDataArray* in = RGBAScalars(caller, rgba, output);
  if (!in)
  {
    return;
  }
  const vtkIdType n = in->GetNumberOfTuples();
  vtkNew<ArrayT> rgb;
  rgb->SetName("RGB");
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double a = in->GetComponent(i, 3);
    for (int k = 0; k < 3; ++k)
    {
      rgb->SetTypedComponent(i, k, convert(in->GetComponent(i, k) + (1.0 - a) * background[k]));
    }
  }
  output->Initialize();
  output->SetDimensions(rgba->GetDimensions());
  output->GetPointData()->SetScalars(rgb);
}
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::CompositeOverBackground(
  vtkImageData* rgba, const double background[3], vtkImageData* output)
{
  CompositeInto<vtkFloatArray>("CompositeOverBackground", rgba, background, output,
    [](double v) { return static_cast<float>(v); });
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::ConvertToUnsignedChar(
  vtkImageData* rgba, const double background[3], vtkImageData* output)
{
  CompositeInto<vtkUnsignedCharArray>("ConvertToUnsignedChar", rgba, background, output,
    [](double v)
    { return static_cast<unsigned char>(std::lround(255.0 * std::min(1.0, std::max(0.0, v)))); });
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::EmulateRayCastImageDisplay(
  vtkImageData* rgba, const double background[3], vtkImageData* output)
{
  vtkDataArray* in = RGBAScalars("EmulateRayCastImageDisplay", rgba, output);
  if (!in)
  {
    return;
  }
  int dims[3];
  rgba->GetDimensions(dims);
  const int w = dims[0], h = dims[1];
  // The 8-bit texture the mapper fills (it truncates).
  std::vector<double> texel(4 * static_cast<size_t>(w) * h);
  for (vtkIdType p = 0; p < static_cast<vtkIdType>(w) * h; ++p)
  {
    for (int k = 0; k < 4; ++k)
    {
      texel[4 * p + k] = std::min(255.0, std::max(0.0, std::floor(255.0 * in->GetComponent(p, k))));
    }
  }
  // Where screen pixel i samples the texture, in texels.
  auto locate = [](int i, int n, int& i0, int& i1, double& f)
  {
    const double pos = n > 1 ? (i + 0.5) * (n - 1) / n : 0.0;
    i0 = static_cast<int>(std::floor(pos));
    i1 = std::min(i0 + 1, n - 1);
    f = pos - i0;
  };
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetName("RGB");
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  for (int j = 0; j < h; ++j)
  {
    int j0, j1;
    double fy;
    locate(j, h, j0, j1, fy);
    for (int i = 0; i < w; ++i)
    {
      int i0, i1;
      double fx;
      locate(i, w, i0, i1, fx);
      double v[4];
      for (int k = 0; k < 4; ++k)
      {
        auto t = [&](int x, int y) { return texel[4 * (static_cast<size_t>(y) * w + x) + k]; };
        v[k] = ((1 - fy) * ((1 - fx) * t(i0, j0) + fx * t(i1, j0)) +
                 fy * ((1 - fx) * t(i0, j1) + fx * t(i1, j1))) /
          255.0;
      }
      for (int k = 0; k < 3; ++k)
      {
        const double c = std::min(1.0, std::max(0.0, v[k] + (1.0 - v[3]) * background[k]));
        rgb->SetTypedComponent(
          static_cast<vtkIdType>(j) * w + i, k, static_cast<unsigned char>(std::lround(255.0 * c)));
      }
    }
  }
  output->Initialize();
  output->SetDimensions(w, h, 1);
  output->GetPointData()->SetScalars(rgb);
}

//------------------------------------------------------------------------------
int vtkTetReferenceRenderer::CompareImages(vtkImageData* a, vtkImageData* b, double stats[3])
{
  stats[0] = stats[1] = stats[2] = 0.0;
  vtkDataArray* da = a ? a->GetPointData()->GetScalars() : nullptr;
  vtkDataArray* db = b ? b->GetPointData()->GetScalars() : nullptr;
  if (!da || !db || da->GetNumberOfTuples() != db->GetNumberOfTuples() ||
    da->GetNumberOfComponents() < 3 || db->GetNumberOfComponents() < 3)
  {
    vtkGenericWarningMacro("CompareImages needs two images of the same size with 3+ components.");
    return 0;
  }
  const double scaleA = vtkUnsignedCharArray::SafeDownCast(da) ? 1.0 : 255.0;
  const double scaleB = vtkUnsignedCharArray::SafeDownCast(db) ? 1.0 : 255.0;
  const vtkIdType n = da->GetNumberOfTuples();
  std::vector<double> diffs(3 * static_cast<size_t>(n));
  double sum = 0.0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      const double diff =
        std::fabs(scaleA * da->GetComponent(i, k) - scaleB * db->GetComponent(i, k));
      diffs[3 * i + k] = diff;
      sum += diff * diff;
    }
  }
  if (diffs.empty())
  {
    return 1;
  }
  stats[0] = std::sqrt(sum / static_cast<double>(diffs.size()));
  const size_t rank = static_cast<size_t>(std::ceil(0.999 * static_cast<double>(diffs.size()))) - 1;
  std::nth_element(diffs.begin(), diffs.begin() + rank, diffs.end());
  stats[1] = diffs[rank];
  stats[2] = *std::max_element(diffs.begin(), diffs.end());
  return 1;
}
