/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastPeelAccumulation.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastPeelAccumulation.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTiledRayCastComputeShader.h"
#include "vtkTiledRayCastVolumetricPeel.h"
#include "vtk_glew.h"

#include "vtkTiledRayCastCompositeFS.h"
#include "vtkTiledRayCastPeelAccumulateCS.h"
#include "vtkTiledRayCastQuadVS.h"
#include "vtkTiledRayCastVolumetricPeelRanges.h"

namespace
{
// Image units of vtkTiledRayCastPeelAccumulateCS.glsl (apart from the traversal's 0 to 3).
const unsigned int SetColorUnit = 4;
const unsigned int SetBackColorUnit = 5;
const unsigned int ColorUnit = 6;
const unsigned int BackColorUnit = 7;
const int GroupSize = 8; // its workgroups, 8x8

vtkTiledRayCastPeelAccumulation* ActiveAccumulation = nullptr;
}

//------------------------------------------------------------------------------
vtkTiledRayCastPeelAccumulation::vtkTiledRayCastPeelAccumulation() = default;

//------------------------------------------------------------------------------
vtkTiledRayCastPeelAccumulation::~vtkTiledRayCastPeelAccumulation()
{
  if (ActiveAccumulation == this)
  {
    ActiveAccumulation = nullptr;
  }
}

//------------------------------------------------------------------------------
vtkTiledRayCastPeelAccumulation* vtkTiledRayCastPeelAccumulation::GetActive()
{
  return ActiveAccumulation;
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastPeelAccumulation::Allocate(vtkOpenGLRenderWindow* window, int width, int height)
{
  for (vtkTextureObject* texture : { this->Color.Get(), this->BackColor.Get() })
  {
    if (texture->GetHandle() && texture->GetWidth() >= static_cast<unsigned int>(width) &&
      texture->GetHeight() >= static_cast<unsigned int>(height))
    {
      continue;
    }
    texture->ReleaseGraphicsResources(window);
    texture->SetContext(window);
    texture->SetInternalFormat(GL_RGBA16);
    texture->SetFormat(GL_RGBA);
    texture->SetDataType(GL_UNSIGNED_SHORT);
    texture->SetMinificationFilter(vtkTextureObject::Nearest);
    texture->SetMagnificationFilter(vtkTextureObject::Nearest);
    if (!texture->Allocate2D(width, height, 4, VTK_UNSIGNED_SHORT))
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastPeelAccumulation::Begin(
  vtkOpenGLRenderWindow* window, int stage, int width, int height, std::string& error)
{
  if (!this->Allocate(window, width, height))
  {
    error = "Cannot allocate the targets that put several volumes in depth order inside VTK's "
            "depth peeling.";
    return false;
  }
  vtkTiledRayCastComputeShader* accumulate = this->Accumulate;
  if (!accumulate->GetHandle() && !accumulate->Build(vtkTiledRayCastPeelAccumulateCS))
  {
    error = "The compute shader that puts several volumes in depth order inside VTK's depth "
            "peeling failed to build (" +
      accumulate->GetError() + ").";
    return false;
  }
  if (stage < 1 || stage > 3)
  {
    error = "Several volumes are put in depth order only in the known stages of VTK's depth "
            "peeling.";
    return false;
  }
  if (!this->Composite[stage - 1])
  {
    // The stage's composite, as a volume's own (vtkTiledRayCastComputePipeline::PreparePeel).
    const std::string version = "#version 430 core\n#define TRC_ENTRY_LIST\n#define "
                                "TRC_PEEL_STAGE " +
      std::to_string(stage) + "\n";
    std::string vs = vtkTiledRayCastQuadVS;
    std::string fs = vtkTiledRayCastCompositeFS;
    vtkShaderProgram::Substitute(vs, "//TRC::Version", version, false);
    vtkShaderProgram::Substitute(fs, "//TRC::Version", version, false);
    vtkShaderProgram::Substitute(fs, "//TRC::Common::Dec", "", false);
    vtkShaderProgram::Substitute(
      fs, "//TRC::VolumetricPeel::Dec", vtkTiledRayCastVolumetricPeelRanges, false);
    vtkShaderProgram* program =
      window->GetShaderCache()->ReadyShaderProgram(vs.c_str(), fs.c_str(), "");
    if (!program || !program->GetCompiled())
    {
      error = "The composite of several volumes inside VTK's depth peeling failed to compile; "
              "see the shader log above.";
      return false;
    }
    this->CompositeVAO[stage - 1]->ShaderProgramChanged();
    this->Composite[stage - 1] = program;
  }
  this->Stage = stage;
  this->Size[0] = width;
  this->Size[1] = height;
  this->Sets = 0;
  ActiveAccumulation = this;
  return true;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastPeelAccumulation::Add(
  vtkOpenGLRenderWindow* window, vtkTextureObject* color, vtkTextureObject* backColor)
{
  vtkTiledRayCastComputeShader* accumulate = this->Accumulate;
  accumulate->Use(window);
  vtkTiledRayCastComputeShader::BindImage(SetColorUnit, color, GL_READ_ONLY, GL_RGBA16);
  vtkTiledRayCastComputeShader::BindImage(SetBackColorUnit, backColor, GL_READ_ONLY, GL_RGBA16);
  vtkTiledRayCastComputeShader::BindImage(ColorUnit, this->Color, GL_READ_WRITE, GL_RGBA16);
  vtkTiledRayCastComputeShader::BindImage(BackColorUnit, this->BackColor, GL_READ_WRITE, GL_RGBA16);
  accumulate->SetUniform2i("in_size", this->Size);
  accumulate->SetUniformi("in_over", this->Sets > 0 ? 1 : 0);
  accumulate->Dispatch(
    (this->Size[0] + GroupSize - 1) / GroupSize, (this->Size[1] + GroupSize - 1) / GroupSize);
  vtkTiledRayCastComputeShader::Barrier(
    GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  for (unsigned int unit : { SetColorUnit, SetBackColorUnit, ColorUnit, BackColorUnit })
  {
    vtkTiledRayCastComputeShader::UnbindImage(unit);
  }
  ++this->Sets;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastPeelAccumulation::Finish(
  vtkOpenGLRenderWindow* window, const vtkTiledRayCastVolumetricPeel& peel)
{
  if (ActiveAccumulation == this)
  {
    ActiveAccumulation = nullptr;
  }
  vtkShaderProgram* p =
    this->Stage >= 1 && this->Stage <= 3 ? this->Composite[this->Stage - 1] : nullptr;
  if (this->Sets == 0 || !p)
  {
    return;
  }
  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthTestSaver(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable cullSaver(state, GL_CULL_FACE);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(state);
  vtkOpenGLState::ScopedglViewport viewportSaver(state);
  state->vtkglViewport(0, 0, this->Size[0], this->Size[1]);
  // Premultiplied colours, with the pass's blend equation (MAX in its peels, add for the
  // remainder), as a volume's own composite.
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_CULL_FACE);
  window->GetShaderCache()->ReadyShaderProgram(p);
  this->Color->Activate();
  this->BackColor->Activate();
  p->SetUniformi("in_color", this->Color->GetTextureUnit());
  p->SetUniformi("in_backColor", this->BackColor->GetTextureUnit());
  peel.SetUniforms(p);
  const float rectangle[4] = { -1.f, -1.f, 1.f, 1.f };
  p->SetUniform4f("in_rectangle", rectangle);
  p->SetUniformf("in_rectangleDepth", 0.f);
  this->CompositeVAO[this->Stage - 1]->Bind();
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  this->CompositeVAO[this->Stage - 1]->Release();
  this->BackColor->Deactivate();
  this->Color->Deactivate();
}

//------------------------------------------------------------------------------
vtkIdType vtkTiledRayCastPeelAccumulation::GetBytes() const
{
  const vtkIdType pixels =
    static_cast<vtkIdType>(this->Color->GetWidth()) * this->Color->GetHeight();
  return this->Color->GetHandle() ? 16 * pixels : 0;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastPeelAccumulation::ReleaseGraphicsResources(vtkWindow* window)
{
  if (ActiveAccumulation == this)
  {
    ActiveAccumulation = nullptr;
  }
  this->Color->ReleaseGraphicsResources(window);
  this->BackColor->ReleaseGraphicsResources(window);
  this->Accumulate->ReleaseProgram();
  for (int k = 0; k < 3; ++k)
  {
    this->Composite[k] = nullptr;
    this->CompositeVAO[k]->ReleaseGraphicsResources();
  }
  this->Sets = 0;
}
