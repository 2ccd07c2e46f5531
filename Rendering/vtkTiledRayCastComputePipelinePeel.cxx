/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastComputePipelinePeel.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkTiledRayCastComputePipeline's part in VTK's dual depth peeling
// (vtkTiledRayCastVolumetricPeel): its own file so that the pipeline's stays under ~800 lines
// (issue 15).
#include "vtkTiledRayCastComputePipeline.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"
#include "vtkTiledRayCastComputeShader.h"
#include "vtk_glew.h"

#include "vtkTiledRayCastCompositeFS.h"
#include "vtkTiledRayCastQuadVS.h"
#include "vtkTiledRayCastTraversalCS.h"
#include "vtkTiledRayCastVolumetricPeelRanges.h"

#include <string>

//------------------------------------------------------------------------------
bool vtkTiledRayCastComputePipeline::PreparePeel(
  vtkOpenGLRenderWindow* window, int stage, std::string& error)
{
  PeelPrograms& peel = this->Peel[stage - 1];
  if (!peel.Built)
  {
    Replacements replacements = ProgramReplacements(this->PeelCommon, false);
    for (auto& r : replacements)
    {
      if (r.first == "//TRC::Version")
      {
        r.second += "#define TRC_PEEL_STAGE " + std::to_string(stage) + "\n";
      }
    }
    replacements.emplace_back("//TRC::VolumetricPeel::Dec", vtkTiledRayCastVolumetricPeelRanges);
    vtkTiledRayCastComputeShader* shader = peel.Traversal;
    const std::string source = Substituted(vtkTiledRayCastTraversalCS, replacements);
    if (!this->ReadyRaster(window, peel.Composite, Substituted(vtkTiledRayCastQuadVS, replacements),
          Substituted(vtkTiledRayCastCompositeFS, replacements), std::string(), error))
    {
      return false;
    }
    if ((source != shader->GetSource() || !shader->GetHandle()) && !shader->Build(source))
    {
      error = "The compute shader of the tiled ray caster's depth peeling failed to build (" +
        shader->GetError() + "). Nothing is drawn.";
      return false;
    }
    peel.Built = true;
  }
  vtkTextureObject* back = this->BackColor;
  if (!back->GetHandle())
  {
    back->SetContext(window);
    back->SetInternalFormat(GL_RGBA16);
    back->SetFormat(GL_RGBA);
    back->SetDataType(GL_UNSIGNED_SHORT);
    back->SetMinificationFilter(vtkTextureObject::Nearest);
    back->SetMagnificationFilter(vtkTextureObject::Nearest);
    if (!back->Allocate2D(this->TargetSize[0], this->TargetSize[1], 4, VTK_UNSIGNED_SHORT))
    {
      error = "Cannot allocate the compute pipeline's back colour for depth peeling. Nothing is "
              "drawn.";
      return false;
    }
  }
  return true;
}
