/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastLighting.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastLighting.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeMapper.h"
#include "vtkVolumeProperty.h"

//------------------------------------------------------------------------------
void vtkTiledRayCastLighting::Compute(vtkRenderer* renderer, vtkVolume* volume, int blendMode)
{
  this->NumberOfLights = 0;
  this->NumberOfPositionalLights = 0;
  this->NumberOfIgnoredLights = 0;
  // Gradients are covectors: an object-space gradient g is M^-T g in world coordinates, M the
  // linear part of the volume's matrix (the layout's shift, a translation, changes nothing).
  double linear[3][3];
  vtkMatrix4x4* matrix = volume->GetMatrix();
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      linear[r][c] = matrix->GetElement(r, c);
    }
  }
  double inverse[3][3];
  vtkMath::Invert3x3(linear, inverse);
  // Column c of M^-T is row c of M^-1.
  for (int c = 0; c < 3; ++c)
  {
    for (int r = 0; r < 3; ++r)
    {
      this->GradientToWorld[3 * c + r] = static_cast<float>(inverse[c][r]);
    }
  }

  vtkVolumeProperty* property = volume->GetProperty();
  this->Enabled =
    property && property->GetShade(0) && blendMode == vtkVolumeMapper::COMPOSITE_BLEND;
  if (!this->Enabled)
  {
    return;
  }
  this->Material[0] = static_cast<float>(property->GetAmbient(0));
  this->Material[1] = static_cast<float>(property->GetDiffuse(0));
  this->Material[2] = static_cast<float>(property->GetSpecular(0));
  this->Material[3] = static_cast<float>(property->GetSpecularPower(0));
  this->TwoSided = renderer->GetTwoSidedLighting() ? 1 : 0;

  // The renderer has placed its headlights and camera lights for this frame's camera
  // (vtkRenderer::UpdateLightsGeometryToFollowCamera): their transformed positions are in world
  // coordinates, as scene lights' are.
  vtkLightCollection* lights = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  for (vtkLight* light = lights->GetNextLight(it); light; light = lights->GetNextLight(it))
  {
    if (!light->GetSwitch() || light->GetIntensity() == 0.0)
    {
      continue;
    }
    double position[3], focal[3], toLight[3];
    light->GetTransformedPosition(position);
    light->GetTransformedFocalPoint(focal);
    vtkMath::Subtract(position, focal, toLight);
    if (vtkMath::Normalize(toLight) == 0.0)
    {
      continue;
    }
    if (light->GetPositional())
    {
      ++this->NumberOfPositionalLights;
    }
    if (this->NumberOfLights == MaximumLights)
    {
      ++this->NumberOfIgnoredLights;
      continue;
    }
    const int i = this->NumberOfLights++;
    const double intensity = light->GetIntensity();
    for (int k = 0; k < 3; ++k)
    {
      this->ToLight[i][k] = static_cast<float>(toLight[k]);
      this->Diffuse[i][k] = static_cast<float>(intensity * light->GetDiffuseColor()[k]);
      this->Specular[i][k] = static_cast<float>(intensity * light->GetSpecularColor()[k]);
    }
  }
}
