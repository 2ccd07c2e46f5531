/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastWarnings.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastWarnings.h"

#include "vtkInformation.h"
#include "vtkObject.h"
#include "vtkOpenGLActor.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkTiledRayCastGradientOpacityNodes.h"
#include "vtkTiledRayCastLighting.h"
#include "vtkVolume.h"
#include "vtkVolumeMapper.h"

//------------------------------------------------------------------------------
void vtkTiledRayCastWarnings::ReportError(const std::string& message)
{
  // The same error every frame would flood the output: say it once until it changes.
  if (message != this->LastError)
  {
    vtkObject* self = this->Reporter;
    vtkErrorWithObjectMacro(self, << message);
    this->LastError = message;
  }
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastWarnings::CheckBlendMode(int blendMode, bool compute)
{
  if (blendMode < vtkVolumeMapper::COMPOSITE_BLEND || blendMode > vtkVolumeMapper::ADDITIVE_BLEND)
  {
    this->ReportError("Blend mode " + std::to_string(blendMode) +
      " is not supported (composite, maximum, minimum and average intensity, additive are). "
      "Nothing is drawn.");
    return false;
  }
  if (blendMode != vtkVolumeMapper::COMPOSITE_BLEND && !compute)
  {
    this->ReportError("Blend modes other than composite need the compute pipeline (OpenGL 4.3). "
                      "Nothing is drawn.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastWarnings::WarnLighting(const vtkTiledRayCastLighting& lighting,
  const vtkTiledRayCastGradientOpacityNodes& gradientOpacity, bool cellScalars)
{
  vtkObject* self = this->Reporter;
  if (lighting.NumberOfPositionalLights > 0 && !this->WarnedPositionalLights)
  {
    vtkWarningWithObjectMacro(self,
      "Shading lights every light as a directional one: a "
      "positional light shines from its position towards its focal "
      "point, without attenuation or cone.");
    this->WarnedPositionalLights = true;
  }
  if (lighting.NumberOfIgnoredLights > 0 && !this->WarnedIgnoredLights)
  {
    vtkWarningWithObjectMacro(self,
      "Shading uses the first " << vtkTiledRayCastLighting::MaximumLights << " lights that are on; "
                                << lighting.NumberOfIgnoredLights << " more are ignored.");
    this->WarnedIgnoredLights = true;
  }
  if (gradientOpacity.Approximated && !this->WarnedGradientOpacity)
  {
    vtkWarningWithObjectMacro(self,
      "The gradient opacity function has intervals of another midpoint or sharpness than 0.5 and "
      "0, or more than "
        << vtkTiledRayCastGradientOpacityNodes::MaximumNodes
        << " nodes: it is sampled (linear between samples).");
    this->WarnedGradientOpacity = true;
  }
  if (lighting.Enabled && cellScalars && !this->WarnedShadedCellScalars)
  {
    vtkWarningWithObjectMacro(self,
      "Shading cell scalars: they are constant per cell, their "
      "gradient is zero, so only the ambient term lights them.");
    this->WarnedShadedCellScalars = true;
  }
}

//------------------------------------------------------------------------------
void vtkTiledRayCastWarnings::WarnTranslucentGeometry(vtkRenderer* ren, vtkVolume* vol)
{
  vtkObject* self = this->Reporter;
  // Translucent polygons are drawn before volumes without depth (VTK's order), so the volume
  // lands over them whatever their depth. Said once. With depth peeling for volumes the compute
  // pipeline takes part in the peeling and this is not called; the fragment pipeline's volume
  // is drawn after the peeling (the volume's property keys then carry the peeling pass's
  // depth-mask override).
  vtkInformation* keys = vol->GetPropertyKeys();
  bool translucentGeometry = keys && keys->Has(vtkOpenGLActor::GLDepthMaskOverride());
  vtkPropCollection* props = ren->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  for (vtkProp* prop = props->GetNextProp(it);
       prop && !translucentGeometry && !this->WarnedTranslucentGeometry;
       prop = props->GetNextProp(it))
  {
    translucentGeometry = prop != vol && prop->GetVisibility() && !vtkVolume::SafeDownCast(prop) &&
      prop->HasTranslucentPolygonalGeometry();
  }
  if (translucentGeometry && !this->WarnedTranslucentGeometry)
  {
    vtkWarningWithObjectMacro(self,
      "Translucent polygonal geometry in the same renderer is not composited "
      "with the volume (it is drawn before it, as for VTK's projected tetrahedra "
      "mapper). Turn on the renderer's depth peeling for volumes (SetUseDepthPeeling "
      "and SetUseDepthPeelingForVolumes) to composite them in depth order (the compute "
      "pipeline with composite blending takes part), make that geometry opaque, or "
      "render it in another renderer.");
    this->WarnedTranslucentGeometry = true;
  }
}

//------------------------------------------------------------------------------
void vtkTiledRayCastWarnings::WarnAfterFrame(
  vtkIdType raysStopped, vtkIdType raysIncomplete, vtkIdType entries)
{
  vtkObject* self = this->Reporter;
  if (raysStopped > 0 && !this->WarnedStoppedRays)
  {
    vtkWarningWithObjectMacro(self, << raysStopped
                                    << " rays reached the bound of steps in one boundary layer and "
                                       "were stopped; the mesh's neighbour links may loop.");
    this->WarnedStoppedRays = true;
  }
  if (raysIncomplete > 0)
  {
    // Every time: each is a frame drawn with layers missing, which the next frames are not.
    vtkWarningWithObjectMacro(
      self, << raysIncomplete
            << " rays of a recent frame missed boundary layers: the view asked for " << entries
            << " ray entries, far more than the frames before it, and the entry list "
               "did not hold them. The list has grown to fit; turn "
               "SynchronousStatistics on to verify every frame.");
  }
}
