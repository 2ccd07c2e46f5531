/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetReferenceShading.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetReferenceShading.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkPiecewiseFunction.h"
#include "vtkTetReferenceMesh.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>

namespace
{
// `point` through the row-major 4x4 `m` (homogeneous, divided by w).
void TransformPoint(vtkMatrix4x4* m, const double point[3], double out[3])
{
  const double in[4] = { point[0], point[1], point[2], 1.0 };
  double h[4];
  m->MultiplyPoint(in, h);
  for (int k = 0; k < 3; ++k)
  {
    out[k] = h[k] / h[3];
  }
}
}

//------------------------------------------------------------------------------
void vtkTetReferenceShading::Initialize(vtkVolumeProperty* property, vtkLightCollection* lights,
  vtkCamera* camera, bool twoSided, const vtkTetReferenceMesh* mesh)
{
  this->Lights.clear();
  this->Mesh = mesh;
  this->GradientOpacity =
    property && mesh && property->HasGradientOpacity(0) && !property->GetDisableGradientOpacity(0)
    ? property->GetStoredGradientOpacity(0)
    : nullptr;
  this->Enabled = property && property->GetShade(0) && camera && mesh;
  if (!this->Enabled)
  {
    return;
  }
  this->TwoSided = twoSided;
  this->Ambient = property->GetAmbient(0);
  this->Diffuse = property->GetDiffuse(0);
  this->Specular = property->GetSpecular(0);
  this->SpecularPower = property->GetSpecularPower(0);
  if (!lights)
  {
    return;
  }
  lights->InitTraversal();
  for (vtkLight* light = lights->GetNextItem(); light; light = lights->GetNextItem())
  {
    if (!light->GetSwitch() || light->GetIntensity() == 0.0)
    {
      continue;
    }
    // Where the light is and what it points at, in world coordinates, as the renderer places
    // them before it draws (vtkRenderer::UpdateLightsGeometryToFollowCamera).
    double position[3], focal[3];
    if (light->LightTypeIsHeadlight())
    {
      camera->GetPosition(position);
      camera->GetFocalPoint(focal);
    }
    else if (light->LightTypeIsCameraLight())
    {
      vtkMatrix4x4* toWorld = camera->GetCameraLightTransformMatrix();
      TransformPoint(toWorld, light->GetPosition(), position);
      TransformPoint(toWorld, light->GetFocalPoint(), focal);
    }
    else
    {
      light->GetTransformedPosition(position);
      light->GetTransformedFocalPoint(focal);
    }
    Light l;
    vtkMath::Subtract(position, focal, l.ToLight);
    if (vtkMath::Normalize(l.ToLight) == 0.0)
    {
      continue; // no direction: the light lights nothing
    }
    const double intensity = light->GetIntensity();
    const double* diffuse = light->GetDiffuseColor();
    const double* specular = light->GetSpecularColor();
    for (int k = 0; k < 3; ++k)
    {
      l.Diffuse[k] = intensity * diffuse[k];
      l.Specular[k] = intensity * specular[k];
    }
    this->Lights.push_back(l);
  }
}

//------------------------------------------------------------------------------
bool vtkTetReferenceShading::DependsOnGradient(vtkVolumeProperty* property)
{
  if (!property)
  {
    return false;
  }
  if (property->GetShade(0))
  {
    return true;
  }
  vtkPiecewiseFunction* f = property->HasGradientOpacity(0) &&
      !property->GetDisableGradientOpacity(0)
    ? property->GetStoredGradientOpacity(0)
    : nullptr;
  // A function that is 1 everywhere changes nothing (VTK creates one wherever a property is
  // copied or its gradient opacity is read).
  bool changes = f && f->GetSize() > 0 && !f->GetClamping();
  for (int i = 0; f && i < f->GetSize() && !changes; ++i)
  {
    double node[4];
    f->GetNodeValue(i, node);
    changes = node[1] != 1.0;
  }
  return changes;
}

//------------------------------------------------------------------------------
double vtkTetReferenceShading::OpacityScale(vtkIdType tet) const
{
  if (!this->GradientOpacity)
  {
    return 1.0;
  }
  double gradient[3];
  Gradient(*this->Mesh, tet, gradient);
  const double value = this->GradientOpacity->GetValue(vtkMath::Norm(gradient));
  return std::min(std::max(value, 0.0), 1.0);
}

//------------------------------------------------------------------------------
void vtkTetReferenceShading::Gradient(
  const vtkTetReferenceMesh& mesh, vtkIdType tet, double gradient[3])
{
  gradient[0] = gradient[1] = gradient[2] = 0.0;
  if (mesh.CellScalars)
  {
    return;
  }
  const vtkIdType* ids = mesh.Tets.data() + 4 * static_cast<size_t>(tet);
  const double* p0 = &mesh.Points[3 * ids[0]];
  const double s0 = mesh.Scalars[ids[0]];
  // The rows of A are the edges from point 0, b the scalar's changes along them: A g = b.
  double a[3][3];
  double b[3];
  for (int i = 0; i < 3; ++i)
  {
    const double* p = &mesh.Points[3 * ids[i + 1]];
    vtkMath::Subtract(p, p0, a[i]);
    b[i] = mesh.Scalars[ids[i + 1]] - s0;
  }
  if (!std::isfinite(b[0]) || !std::isfinite(b[1]) || !std::isfinite(b[2]))
  {
    return; // a non-finite scalar: the tetrahedron is transparent anyway
  }
  if (vtkMath::Determinant3x3(a) == 0.0)
  {
    return; // no volume (the renderer skips such tetrahedra)
  }
  vtkMath::LinearSolve3x3(a, b, gradient);
}

//------------------------------------------------------------------------------
void vtkTetReferenceShading::Factors(
  vtkIdType tet, const double d[3], double scale[3], double offset[3]) const
{
  double normal[3];
  Gradient(*this->Mesh, tet, normal);
  // The normal points down the gradient (towards lower scalars); zero stays zero.
  vtkMath::MultiplyScalar(normal, -1.0);
  vtkMath::Normalize(normal);
  double toViewer[3] = { -d[0], -d[1], -d[2] };
  vtkMath::Normalize(toViewer);
  double diffuse[3] = { 0.0, 0.0, 0.0 };
  double specular[3] = { 0.0, 0.0, 0.0 };
  for (const Light& light : this->Lights)
  {
    double half[3];
    vtkMath::Add(light.ToLight, toViewer, half);
    const double halfLength = vtkMath::Norm(half);
    double nl = vtkMath::Dot(normal, light.ToLight);
    double nh = halfLength > 0.0 ? vtkMath::Dot(normal, half) / halfLength : 0.0;
    if (this->TwoSided)
    {
      nl = std::abs(nl);
      nh = std::abs(nh);
    }
    if (nl <= 0.0)
    {
      continue;
    }
    const double highlight = nh > 0.0 ? std::pow(nh, this->SpecularPower) : 0.0;
    for (int k = 0; k < 3; ++k)
    {
      diffuse[k] += nl * light.Diffuse[k];
      specular[k] += highlight * light.Specular[k];
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    scale[k] = this->Ambient + this->Diffuse * diffuse[k];
    offset[k] = this->Specular * specular[k];
  }
}

//------------------------------------------------------------------------------
void vtkTetReferenceShading::Apply(
  vtkIdType tet, const double d[3], double alpha, double rgb[3]) const
{
  if (!(alpha > 0.0))
  {
    return;
  }
  double scale[3], offset[3];
  this->Factors(tet, d, scale, offset);
  for (int k = 0; k < 3; ++k)
  {
    rgb[k] = scale[k] * rgb[k] + offset[k] * alpha;
  }
}
