/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastFrameGeometry.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastFrameGeometry.h"

#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"

#include <algorithm>
#include <cmath>

namespace
{
// A column-major float copy of a row-major double 4x4 matrix, as GLSL's mat4 expects.
void ToColumnMajor(const double m[16], float out[16])
{
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      out[4 * c + r] = static_cast<float>(m[4 * r + c]);
    }
  }
}

// The smallest and largest value of dot(plane.xyz, x) + plane.w over the corners of a box.
void PlaneRangeOverBox(const double plane[4], const double bounds[6], double& lo, double& hi)
{
  lo = VTK_DOUBLE_MAX;
  hi = VTK_DOUBLE_MIN;
  for (int c = 0; c < 8; ++c)
  {
    const double p[3] = { bounds[c & 1], bounds[2 + ((c >> 1) & 1)], bounds[4 + ((c >> 2) & 1)] };
    const double d = plane[0] * p[0] + plane[1] * p[1] + plane[2] * p[2] + plane[3];
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
}
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastFrameGeometry::Compute(
  vtkRenderer* ren, vtkVolume* vol, const double shiftBy[3], const double meshBounds[6])
{
  this->Valid = false;
  const double aspect = ren->GetTiledAspectRatio();
  vtkCamera* camera = ren->GetActiveCamera();
  vtkMatrix4x4* worldToClip = camera->GetCompositeProjectionTransformMatrix(aspect, -1, 1);

  // Shifted object coordinates (those of the GPU layout) to clip coordinates, in double.
  vtkNew<vtkMatrix4x4> shift;
  for (int i = 0; i < 3; ++i)
  {
    shift->SetElement(i, 3, shiftBy[i]);
  }
  vtkNew<vtkMatrix4x4> objectToWorld;
  vtkMatrix4x4::Multiply4x4(vol->GetMatrix(), shift, objectToWorld);
  std::copy(objectToWorld->GetData(), objectToWorld->GetData() + 16, this->ShiftedObjectToWorld);
  vtkNew<vtkMatrix4x4> objectToClip;
  vtkMatrix4x4::Multiply4x4(worldToClip, objectToWorld, objectToClip);
  vtkNew<vtkMatrix4x4> clipToObject;
  vtkMatrix4x4::Invert(objectToClip, clipToObject);
  ToColumnMajor(objectToClip->GetData(), this->ObjectToClip);

  double linear[3][3];
  double norm = 0;
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      linear[r][c] = vol->GetMatrix()->GetElement(r, c);
      this->ObjectToWorld[3 * c + r] = static_cast<float>(linear[r][c]);
      norm += linear[r][c] * linear[r][c];
    }
  }
  this->ObjectToWorldNorm = std::sqrt(norm);
  this->Mirrored = vtkMath::Determinant3x3(linear) < 0;

  // Near and far points of the rays through NDC (0,0), (1,0) and (0,1): both are affine in
  // NDC for VTK's perspective and parallel cameras, and so are the clip-space w's.
  auto unproject = [&](double x, double y, double z, double q[3], double& w)
  {
    double h[4] = { x, y, z, 1.0 };
    clipToObject->MultiplyPoint(h, h);
    for (int i = 0; i < 3; ++i)
    {
      q[i] = h[i] / h[3];
    }
    w = 1.0 / h[3];
  };
  double nearPt[3][3], farPt[3][3], wn[3], wf[3];
  const double corners[3][2] = { { 0, 0 }, { 1, 0 }, { 0, 1 } };
  for (int k = 0; k < 3; ++k)
  {
    unproject(corners[k][0], corners[k][1], -1.0, nearPt[k], wn[k]);
    unproject(corners[k][0], corners[k][1], 1.0, farPt[k], wf[k]);
  }
  double dir[3][3];
  for (int k = 0; k < 3; ++k)
  {
    for (int i = 0; i < 3; ++i)
    {
      dir[k][i] = farPt[k][i] - nearPt[k][i];
    }
  }
  // lambda = 0 where the central ray passes closest to the mesh centre (the origin of the
  // shifted coordinates), so that lambda stays small where the mesh is.
  const double d2 = vtkMath::Dot(dir[0], dir[0]);
  double muCentre = d2 > 0 ? -vtkMath::Dot(nearPt[0], dir[0]) / d2 : 0.0;
  muCentre = std::min(std::max(muCentre, 0.0), 1.0);
  this->LambdaNear = static_cast<float>(-muCentre);
  for (int i = 0; i < 3; ++i)
  {
    const double o0 = nearPt[0][i] + muCentre * dir[0][i];
    const double ox = nearPt[1][i] + muCentre * dir[1][i] - o0;
    const double oy = nearPt[2][i] + muCentre * dir[2][i] - o0;
    this->RayOrigin[0][i] = static_cast<float>(o0);
    this->RayOrigin[1][i] = static_cast<float>(ox);
    this->RayOrigin[2][i] = static_cast<float>(oy);
    this->RayDir[0][i] = static_cast<float>(dir[0][i]);
    this->RayDir[1][i] = static_cast<float>(dir[1][i] - dir[0][i]);
    this->RayDir[2][i] = static_cast<float>(dir[2][i] - dir[0][i]);
  }
  this->WNear[0] = static_cast<float>(wn[0]);
  this->WNear[1] = static_cast<float>(wn[1] - wn[0]);
  this->WNear[2] = static_cast<float>(wn[2] - wn[0]);
  this->WFar[0] = static_cast<float>(wf[0]);
  this->WFar[1] = static_cast<float>(wf[1] - wf[0]);
  this->WFar[2] = static_cast<float>(wf[2] - wf[0]);

  // The near plane, positive on the camera's side of nothing: beyond it, towards the scene.
  double ex[3], ey[3], normal[3];
  for (int i = 0; i < 3; ++i)
  {
    ex[i] = nearPt[1][i] - nearPt[0][i];
    ey[i] = nearPt[2][i] - nearPt[0][i];
  }
  vtkMath::Cross(ex, ey, normal);
  if (vtkMath::Dot(normal, dir[0]) < 0)
  {
    for (double& v : normal)
    {
      v = -v;
    }
  }
  vtkMath::Normalize(normal);
  const double offset = -vtkMath::Dot(normal, nearPt[0]);
  for (int i = 0; i < 3; ++i)
  {
    this->NearPlane[i] = static_cast<float>(normal[i]);
  }
  this->NearPlane[3] = static_cast<float>(offset);
  // Only when the near plane cuts the mesh's bounds can a ray start inside the mesh.
  const double nearPlane[4] = { normal[0], normal[1], normal[2], offset };
  double lo, hi;
  PlaneRangeOverBox(nearPlane, meshBounds, lo, hi);
  this->NearPlaneCutsMesh = lo < 0 && hi > 0;
  this->BoundsCoverage = this->ComputeBoundsCoverage(meshBounds);
  this->Valid = std::isfinite(this->RayDir[0][0]) && std::isfinite(this->RayOrigin[0][0]);
  return this->Valid;
}

//------------------------------------------------------------------------------
double vtkTiledRayCastFrameGeometry::ComputeBoundsCoverage(const double meshBounds[6]) const
{
  double lo[2] = { 1, 1 };
  double hi[2] = { -1, -1 };
  for (int c = 0; c < 8; ++c)
  {
    const double p[3] = { meshBounds[c & 1], meshBounds[2 + ((c >> 1) & 1)],
      meshBounds[4 + ((c >> 2) & 1)] };
    double clip[4];
    for (int row = 0; row < 4; ++row)
    {
      const float* m = this->ObjectToClip;
      clip[row] = m[row] * p[0] + m[4 + row] * p[1] + m[8 + row] * p[2] + m[12 + row];
    }
    if (!(clip[3] > 0))
    {
      return 1.0; // a corner behind the eye: the bounds may cover the whole view
    }
    for (int a = 0; a < 2; ++a)
    {
      lo[a] = std::min(lo[a], clip[a] / clip[3]);
      hi[a] = std::max(hi[a], clip[a] / clip[3]);
    }
  }
  double area = 1;
  for (int a = 0; a < 2; ++a)
  {
    area *= std::max(0.0, std::min(hi[a], 1.0) - std::max(lo[a], -1.0)) / 2.0;
  }
  return area;
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastFrameGeometry::ComputeClippingPlanes(
  vtkPlaneCollection* planes, const double meshBounds[6])
{
  this->NumberOfClippingPlanes = 0;
  this->ClippedAway = false;
  const int given = planes ? planes->GetNumberOfItems() : 0;
  for (int k = 0; k < std::min(given, MaximumClippingPlanes); ++k)
  {
    // A plane (n, -n.o) as a row vector times the shifted-object-to-world matrix: the same
    // function of the point, so the kept side stays the kept side under any matrix (mirrors too).
    vtkPlane* plane = planes->GetItem(k);
    double normal[3], origin[3];
    plane->GetNormal(normal);
    plane->GetOrigin(origin);
    const double world[4] = { normal[0], normal[1], normal[2], -vtkMath::Dot(normal, origin) };
    double object[4];
    for (int c = 0; c < 4; ++c)
    {
      object[c] = 0;
      for (int r = 0; r < 4; ++r)
      {
        object[c] += world[r] * this->ShiftedObjectToWorld[4 * r + c];
      }
    }
    const double length = std::sqrt(vtkMath::Dot(object, object));
    if (!(length > 0) || !std::isfinite(length) || !std::isfinite(object[3]))
    {
      continue; // a plane without a normal clips nothing
    }
    double lo, hi;
    PlaneRangeOverBox(object, meshBounds, lo, hi);
    this->ClippedAway = this->ClippedAway || hi < 0;
    float* out = this->ClippingPlanes[this->NumberOfClippingPlanes++];
    for (int c = 0; c < 4; ++c)
    {
      out[c] = static_cast<float>(object[c] / length);
    }
  }
  return given <= MaximumClippingPlanes;
}
