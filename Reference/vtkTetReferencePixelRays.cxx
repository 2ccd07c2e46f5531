/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetReferencePixelRays.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetReferencePixelRays.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"

#include <algorithm>
#include <cmath>

//------------------------------------------------------------------------------
void vtkTetReferencePixelRays::SetUp(vtkCamera* camera, int width, int height,
  const double offset[2], const float* depth, const double* center, vtkPlaneCollection* planes)
{
  this->Width = width;
  this->Height = height;
  this->OffsetX = offset[0];
  this->OffsetY = offset[1];
  this->Depth = depth;
  this->Center = center;
  // Clip coordinates of the camera to world coordinates.
  vtkMatrix4x4::DeepCopy(this->Inverse,
    camera->GetCompositeProjectionTransformMatrix(static_cast<double>(width) / height, -1.0, 1.0));
  vtkMatrix4x4::Invert(this->Inverse, this->Inverse);
  this->SetClippingPlanes(planes);
}

//------------------------------------------------------------------------------
bool vtkTetReferencePixelRays::Direction(
  int i, int j, double& x, double& y, double nearP[3], double d[3], double& dd) const
{
  x = 2.0 * (i + this->OffsetX) / this->Width - 1.0;
  y = 2.0 * (j + this->OffsetY) / this->Height - 1.0;
  double farP[3];
  this->Unproject(x, y, -1.0, nearP);
  this->Unproject(x, y, 1.0, farP);
  for (int k = 0; k < 3; ++k)
  {
    d[k] = farP[k] - nearP[k];
  }
  dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  return dd > 0.0 && std::isfinite(dd);
}

//------------------------------------------------------------------------------
void vtkTetReferencePixelRays::SetClippingPlanes(vtkPlaneCollection* planes)
{
  this->Clipping.clear();
  for (int k = 0; planes && k < planes->GetNumberOfItems(); ++k)
  {
    vtkPlane* plane = planes->GetItem(k);
    std::array<double, 4> h;
    plane->GetNormal(h.data());
    double origin[3];
    plane->GetOrigin(origin);
    h[3] = 0.0;
    for (int r = 0; r < 3; ++r)
    {
      h[3] -= h[r] * (origin[r] - (this->Center ? this->Center[r] : 0.0));
    }
    if (h[0] != 0.0 || h[1] != 0.0 || h[2] != 0.0)
    {
      this->Clipping.push_back(h);
    }
  }
}

//------------------------------------------------------------------------------
void vtkTetReferencePixelRays::Unproject(double x, double y, double z, double p[3]) const
{
  const double* inverse = this->Inverse;
  double h[4];
  for (int r = 0; r < 4; ++r)
  {
    h[r] =
      inverse[4 * r] * x + inverse[4 * r + 1] * y + inverse[4 * r + 2] * z + inverse[4 * r + 3];
  }
  for (int r = 0; r < 3; ++r)
  {
    p[r] = this->Center ? h[r] / h[3] - this->Center[r] : h[r] / h[3];
  }
}

//------------------------------------------------------------------------------
bool vtkTetReferencePixelRays::Range(double x, double y, long long pixel, const double nearP[3],
  const double d[3], double dd, double& lambdaMin, double& lambdaMax) const
{
  lambdaMax = 1.0;
  if (this->Depth && this->Depth[pixel] < 1.0f)
  {
    double p[3];
    this->Unproject(x, y, 2.0 * this->Depth[pixel] - 1.0, p);
    lambdaMax =
      ((p[0] - nearP[0]) * d[0] + (p[1] - nearP[1]) * d[1] + (p[2] - nearP[2]) * d[2]) / dd;
    lambdaMax = std::min(1.0, std::max(0.0, lambdaMax));
  }
  // The kept half-spaces of the clipping planes cut the ray to [lambdaMin, lambdaMax].
  lambdaMin = 0.0;
  for (const std::array<double, 4>& h : this->Clipping)
  {
    const double at0 = h[0] * nearP[0] + h[1] * nearP[1] + h[2] * nearP[2] + h[3];
    const double rate = h[0] * d[0] + h[1] * d[1] + h[2] * d[2];
    if (rate > 0.0)
    {
      lambdaMin = std::max(lambdaMin, -at0 / rate);
    }
    else if (rate < 0.0)
    {
      lambdaMax = std::min(lambdaMax, -at0 / rate);
    }
    else if (at0 < 0.0)
    {
      lambdaMax = -1.0;
    }
  }
  return lambdaMax > 0.0 && lambdaMax > lambdaMin;
}

//------------------------------------------------------------------------------
bool vtkTetReferencePixelRays::Get(
  int i, int j, double origin[3], double d[3], double& zmin, double& zmax) const
{
  const long long pixel = static_cast<long long>(j) * this->Width + i;
  double x, y, nearP[3], dd;
  if (!this->Direction(i, j, x, y, nearP, d, dd))
  {
    return false;
  }
  double lambdaMin, lambdaMax;
  if (!this->Range(x, y, pixel, nearP, d, dd, lambdaMin, lambdaMax))
  {
    return false;
  }
  // Measure the ray from its point nearest to the mesh centre (the origin here): the vertex
  // coordinates of the ray frame then stay as small as the mesh.
  const double lambdaC =
    std::min(lambdaMax, std::max(0.0, -(nearP[0] * d[0] + nearP[1] * d[1] + nearP[2] * d[2]) / dd));
  for (int k = 0; k < 3; ++k)
  {
    origin[k] = nearP[k] + lambdaC * d[k];
  }
  zmin = lambdaMin - lambdaC;
  zmax = lambdaMax - lambdaC;
  return true;
}

//------------------------------------------------------------------------------
bool vtkTetReferencePixelRays::GetWorld(int i, int j, double nearP[3], double d[3],
  double& volumeMin, double& volumeMax, bool& volumes) const
{
  const long long pixel = static_cast<long long>(j) * this->Width + i;
  double x, y, dd;
  if (!this->Direction(i, j, x, y, nearP, d, dd))
  {
    return false;
  }
  volumes = this->Range(x, y, pixel, nearP, d, dd, volumeMin, volumeMax);
  return true;
}

//------------------------------------------------------------------------------
double vtkTetReferencePixelRays::LambdaAtDepth(
  int i, int j, const double nearP[3], const double d[3], double z) const
{
  const double x = 2.0 * (i + this->OffsetX) / this->Width - 1.0;
  const double y = 2.0 * (j + this->OffsetY) / this->Height - 1.0;
  double p[3];
  this->Unproject(x, y, 2.0 * z - 1.0, p);
  const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  return ((p[0] - nearP[0]) * d[0] + (p[1] - nearP[1]) * d[1] + (p[2] - nearP[2]) * d[2]) / dd;
}
