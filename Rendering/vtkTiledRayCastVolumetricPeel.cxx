/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastVolumetricPeel.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastVolumetricPeel.h"

#include "vtkAbstractVolumeMapper.h"
#include "vtkDualDepthPeelingPass.h"
#include "vtkInformation.h"
#include "vtkInformationObjectBaseVectorKey.h"
#include "vtkOpenGLRenderPass.h"
#include "vtkVolume.h"

#include <string>

//------------------------------------------------------------------------------
vtkTiledRayCastVolumetricPeel::Stage vtkTiledRayCastVolumetricPeel::Update(
  vtkAbstractVolumeMapper* mapper, vtkVolume* volume)
{
  this->Pass = vtkTiledRayCastVolumetricPeel::FindPass(volume);
  this->Mapper = mapper;
  this->Volume = volume;
  if (!this->Pass)
  {
    this->CurrentStage = NotPeeling;
    return this->CurrentStage;
  }
  // What the pass would declare in its image ray caster's shader at this stage.
  std::string vertex;
  std::string geometry;
  std::string fragment = "//VTK::DepthPeeling::Dec";
  this->Pass->PreReplaceShaderValues(vertex, geometry, fragment, mapper, volume);
  if (fragment.find("depthRangeTex") != std::string::npos)
  {
    this->CurrentStage = Remainder;
  }
  else if (fragment.find("lastFrontColorTex") != std::string::npos &&
    fragment.find("opaqueDepthTex") != std::string::npos)
  {
    this->CurrentStage = Peel;
  }
  else if (fragment.find("innerDepthTex") != std::string::npos &&
    fragment.find("outerDepthTex") != std::string::npos)
  {
    this->CurrentStage = BeforePeels;
  }
  else
  {
    this->CurrentStage = UnknownStage;
  }
  return this->CurrentStage;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastVolumetricPeel::SetUniforms(vtkShaderProgram* program) const
{
  if (this->Pass)
  {
    this->Pass->SetShaderParameters(program, this->Mapper, this->Volume, nullptr);
  }
}

//------------------------------------------------------------------------------
vtkOpenGLRenderPass* vtkTiledRayCastVolumetricPeel::FindPass(vtkVolume* volume)
{
  // The pass marks the props it draws with itself as a render pass (vtkOpenGLRenderPass's
  // PreRender) for as long as it draws them.
  vtkInformation* keys = volume ? volume->GetPropertyKeys() : nullptr;
  vtkInformationObjectBaseVectorKey* passes = vtkOpenGLRenderPass::RenderPasses();
  if (!keys || !keys->Has(passes))
  {
    return nullptr;
  }
  for (int i = 0; i < passes->Length(keys); ++i)
  {
    if (auto* pass = vtkDualDepthPeelingPass::SafeDownCast(passes->Get(keys, i)))
    {
      return pass;
    }
  }
  return nullptr;
}
