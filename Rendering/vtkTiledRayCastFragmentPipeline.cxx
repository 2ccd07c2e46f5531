/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastFragmentPipeline.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastFragmentPipeline.h"

#include "vtkObject.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTiledRayCastComputePipeline.h"
#include "vtkTiledRayCastComputeShader.h"
#include "vtkTiledRayCastDebugEvent.h"
#include "vtkTiledRayCastPhaseTimers.h"
#include "vtkTiledRayCastStatistics.h"
#include "vtk_glew.h"

#include "vtkTiledRayCastBoundaryFaceFS.h"
#include "vtkTiledRayCastBoundaryFaceVS.h"
#include "vtkTiledRayCastCompositeFS.h"
#include "vtkTiledRayCastCopyFS.h"
#include "vtkTiledRayCastCountFS.h"
#include "vtkTiledRayCastNearSliceFS.h"
#include "vtkTiledRayCastNearSliceGS.h"
#include "vtkTiledRayCastNearSliceVS.h"
#include "vtkTiledRayCastQuadVS.h"
#include "vtkTiledRayCastRayTargets.h"
#include "vtkTiledRayCastTraversalFS.h"
#include "vtkTiledRayCastWalk.h"

#include <algorithm>

// vtkOpenGLCheckErrorMacro (compiled where NDEBUG is not defined) reports with vtkErrorMacro,
// which needs a vtkObject's `this`: the pipeline reports through the frame's reporter (the
// mapper).
#if defined(VTK_REPORT_OPENGL_ERRORS)
#define vtkFragmentPipelineErrorMacro(x) vtkErrorWithObjectMacro(this->Current->Reporter, x)
#define vtkFragmentPipelineCheckErrorMacro(message)                                                \
  vtkOpenGLCheckErrorMacroImpl(vtkFragmentPipelineErrorMacro, message)
#else
#define vtkFragmentPipelineCheckErrorMacro(message)
#endif

namespace
{
// Ray status codes, as in vtkTiledRayCastCommonFS.glsl.
enum RayStatus
{
  StatusMiss = 0,
  StatusActive = 1,
  StatusWaiting = 2,
  StatusDoneDepth = 3,
  StatusDoneOpaque = 4
};

// The depth at which tile rectangles are drawn: halfway, so that the early-z marks of the
// Z-update pass (0 for finished rays, 1 for active ones) cull or pass them.
const float RectangleDepth = 0.0f; // NDC, window depth 0.5

std::string Substituted(
  std::string source, const vtkTiledRayCastFragmentPipeline::Replacements& replacements)
{
  for (const auto& r : replacements)
  {
    vtkShaderProgram::Substitute(source, r.first, r.second, true);
  }
  return source;
}
} // anonymous namespace

//------------------------------------------------------------------------------
vtkTiledRayCastFragmentPipeline::vtkTiledRayCastFragmentPipeline() = default;

//------------------------------------------------------------------------------
vtkTiledRayCastFragmentPipeline::~vtkTiledRayCastFragmentPipeline() = default;

//------------------------------------------------------------------------------
void vtkTiledRayCastFragmentPipeline::Program::Release()
{
  this->Shader = nullptr;
  this->VAO->ReleaseGraphicsResources();
  this->Key.clear();
}

//------------------------------------------------------------------------------
void vtkTiledRayCastFragmentPipeline::Render(const Frame& frame, vtkTiledRayCastProgramSetup& setup,
  vtkTiledRayCastPhaseTimers& timers, vtkTiledRayCastStatistics* stats)
{
  this->Current = &frame;
  this->Setup = &setup;
  this->Stats = stats;
  vtkOpenGLRenderWindow* window = frame.Window;
  this->Queries.Recycle();
  this->PassBlocks.clear();
  this->NearPlaneQuery = 0;
  this->MakeTiles();

  timers.Start(vtkTiledRayCastPhaseTimers::FirstHit);
  this->RenderFirstHit(window);
  timers.Stop(vtkTiledRayCastPhaseTimers::FirstHit);
  // Layers: ray cast, then peel the next boundary layer behind where rays left the mesh, until
  // a peel finds no re-entry.
  int layers = 1;
  int peels = 0;
  const int maxLayers = 1 << 16;
  while (true)
  {
    timers.Start(vtkTiledRayCastPhaseTimers::RayCasting);
    this->RayCastLayer(window);
    timers.Stop(vtkTiledRayCastPhaseTimers::RayCasting);
    if (layers >= maxLayers)
    {
      vtkObject* self = frame.Reporter;
      vtkWarningWithObjectMacro(self, "Stopped after " << maxLayers << " boundary layers.");
      break;
    }
    timers.Start(vtkTiledRayCastPhaseTimers::Peeling);
    const unsigned int reentered = this->Peel(window);
    timers.Stop(vtkTiledRayCastPhaseTimers::Peeling);
    ++peels;
    if (!reentered)
    {
      break;
    }
    ++layers;
  }
  timers.Start(vtkTiledRayCastPhaseTimers::Compositing);
  this->Composite(window);
  timers.Stop(vtkTiledRayCastPhaseTimers::Compositing);
  this->FinishStatistics();
  stats->SetNumberOfLayers(layers);
  stats->SetNumberOfPeelPasses(peels);
  this->Current = nullptr;
  this->Setup = nullptr;
  this->Stats = nullptr;
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastFragmentPipeline::UpdatePrograms(vtkOpenGLRenderWindow* window,
  const std::string& version, const Replacements& mapperCommon, std::string& error)
{
  Replacements common = mapperCommon;
  common.insert(common.begin(), { "//TRC::Version", version });
  common.emplace_back("//TRC::Walk::Dec", vtkTiledRayCastWalk);
  // The raster passes write the entries they find to the ray targets (the compute pipeline lists
  // them instead).
  common.emplace_back("//TRC::RayTargets::Dec", vtkTiledRayCastRayTargets);
  common.emplace_back("//TRC::EntryTarget::Dec", vtkTiledRayCastRayTargets);
  const std::string peelDec = "uniform sampler2D in_previousState;\n"
                              "uniform sampler2D in_previousColor;\n"
                              "uniform sampler2D in_previousEntry;\n"
                              "uniform float in_peelEpsilon;\n";
  // Most fragments of a peel belong to pixels whose ray is not waiting: they leave first.
  const std::string peelEarly = "ivec2 pixel = ivec2(gl_FragCoord.xy);\n"
                                "  vec4 previous = texelFetch(in_previousState, pixel, 0);\n"
                                "  if (trcStatus(previous) != TRC_WAITING)\n"
                                "  {\n    discard;\n  }\n";
  const std::string peelImpl =
    "if (lambda < previous.y - in_peelEpsilon)\n"
    "  {\n    discard;\n  }\n"
    "  vec4 lastEntry = texelFetch(in_previousEntry, pixel, 0);\n"
    "  if (abs(lambda - lastEntry.x) <= in_peelEpsilon &&\n"
    "    (lambda < lastEntry.x || (lambda == lastEntry.x && key <= trcEntryKey(lastEntry))))\n"
    "  {\n    discard;\n  }\n"
    "  lambda = max(lambda, previous.y);\n"
    "  color = texelFetch(in_previousColor, pixel, 0);\n";

  struct Spec
  {
    Program* Target;
    const char* VS;
    const char* GS;
    const char* FS;
    bool Peel;
  };
  const Spec specs[] = {
    { &this->FirstHitProgram, vtkTiledRayCastBoundaryFaceVS, nullptr, vtkTiledRayCastBoundaryFaceFS,
      false },
    { &this->PeelProgram, vtkTiledRayCastBoundaryFaceVS, nullptr, vtkTiledRayCastBoundaryFaceFS,
      true },
    { &this->NearSliceProgram, vtkTiledRayCastNearSliceVS, vtkTiledRayCastNearSliceGS,
      vtkTiledRayCastNearSliceFS, false },
    { &this->TraversalProgram, vtkTiledRayCastQuadVS, nullptr, vtkTiledRayCastTraversalFS, false },
    { &this->CopyProgram, vtkTiledRayCastQuadVS, nullptr, vtkTiledRayCastCopyFS, false },
    { &this->CountProgram, vtkTiledRayCastQuadVS, nullptr, vtkTiledRayCastCountFS, false },
    { &this->CompositeProgram, vtkTiledRayCastQuadVS, nullptr, vtkTiledRayCastCompositeFS, false },
  };
  for (const Spec& spec : specs)
  {
    std::vector<std::pair<std::string, std::string>> replacements = common;
    replacements.emplace_back("//TRC::Peel::Dec", spec.Peel ? peelDec : std::string());
    replacements.emplace_back("//TRC::Peel::Early", spec.Peel ? peelEarly : std::string());
    replacements.emplace_back("//TRC::Peel::Impl", spec.Peel ? peelImpl : std::string());
    const std::string vs = Substituted(spec.VS, replacements);
    const std::string fs = Substituted(spec.FS, replacements);
    const std::string gs = spec.GS ? Substituted(spec.GS, replacements) : std::string();
    const std::string key = vs + fs + gs;
    if (key == spec.Target->Key && spec.Target->Shader)
    {
      continue;
    }
    vtkShaderProgram* shader =
      window->GetShaderCache()->ReadyShaderProgram(vs.c_str(), fs.c_str(), gs.c_str());
    if (!shader || !shader->GetCompiled())
    {
      error = "A shader of the tiled ray caster failed to compile or link; see the shader log "
              "above. Nothing is drawn.";
      spec.Target->Shader = nullptr;
      return false;
    }
    if (shader != spec.Target->Shader)
    {
      spec.Target->Shader = shader;
      spec.Target->VAO->ShaderProgramChanged();
    }
    spec.Target->Key = key;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastFragmentPipeline::UpdateTargets(
  vtkOpenGLRenderWindow* window, int width, int height, std::string& error)
{
  if (width <= this->TargetSize[0] && height <= this->TargetSize[1] &&
    this->Framebuffer[0]->GetFBOIndex() != 0)
  {
    return true;
  }
  width = std::max(width, this->TargetSize[0]);
  height = std::max(height, this->TargetSize[1]);
  vtkOpenGLState* ostate = window->GetState();
  auto setup = [&](vtkTextureObject* tex, unsigned int internal, unsigned int format, int comps)
  {
    tex->SetContext(window);
    tex->SetInternalFormat(internal);
    tex->SetFormat(format);
    tex->SetDataType(GL_FLOAT);
    tex->SetMinificationFilter(vtkTextureObject::Nearest);
    tex->SetMagnificationFilter(vtkTextureObject::Nearest);
    tex->SetWrapS(vtkTextureObject::ClampToEdge);
    tex->SetWrapT(vtkTextureObject::ClampToEdge);
    if (tex->GetHandle() && tex->GetWidth() > 0)
    {
      tex->Resize(width, height);
      return true;
    }
    return tex->Allocate2D(width, height, comps, VTK_FLOAT);
  };
  bool ok = true;
  for (int q = 0; q < 2; ++q)
  {
    ok = ok && setup(this->State[q], GL_RGBA32F, GL_RGBA, 4);
    ok = ok && setup(this->Color[q], GL_RGBA32F, GL_RGBA, 4);
    ok = ok && setup(this->Entry[q], GL_RGBA32F, GL_RGBA, 4);
  }
  vtkTextureObject* depth = this->Depth;
  depth->SetContext(window);
  depth->SetMinificationFilter(vtkTextureObject::Nearest);
  depth->SetMagnificationFilter(vtkTextureObject::Nearest);
  if (depth->GetHandle() && depth->GetWidth() > 0)
  {
    depth->Resize(width, height);
  }
  else
  {
    ok = ok && depth->AllocateDepth(width, height, vtkTextureObject::Float32);
  }
  if (!ok)
  {
    error = "Cannot allocate the ray-casting render targets. Nothing is drawn.";
    return false;
  }
  ostate->PushFramebufferBindings();
  for (int q = 0; q < 2; ++q)
  {
    vtkOpenGLFramebufferObject* fbo = this->Framebuffer[q];
    fbo->SetContext(window);
    fbo->Bind();
    fbo->AddColorAttachment(0, this->State[q]);
    fbo->AddColorAttachment(1, this->Color[q]);
    fbo->AddColorAttachment(2, this->Entry[q]);
    fbo->AddDepthAttachment(this->Depth);
    fbo->ActivateDrawBuffers(3);
    if (!fbo->CheckFrameBufferStatus(GL_FRAMEBUFFER))
    {
      ok = false;
    }
  }
  ostate->PopFramebufferBindings();
  if (!ok)
  {
    error = "The ray-casting framebuffer is incomplete on this GPU. Nothing is drawn.";
    return false;
  }
  this->TargetSize[0] = width;
  this->TargetSize[1] = height;
  return true;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastFragmentPipeline::ActivateTextures(bool activate)
{
  for (int q = 0; q < 2; ++q)
  {
    for (vtkTextureObject* t :
      { this->State[q].GetPointer(), this->Color[q].GetPointer(), this->Entry[q].GetPointer() })
    {
      if (activate)
      {
        t->Activate();
      }
      else
      {
        t->Deactivate();
      }
    }
  }
}

//------------------------------------------------------------------------------
void vtkTiledRayCastFragmentPipeline::ReleaseTargets(vtkWindow* window)
{
  for (int q = 0; q < 2; ++q)
  {
    this->State[q]->ReleaseGraphicsResources(window);
    this->Color[q]->ReleaseGraphicsResources(window);
    this->Entry[q]->ReleaseGraphicsResources(window);
    this->Framebuffer[q]->ReleaseGraphicsResources(window);
  }
  this->Depth->ReleaseGraphicsResources(window);
  this->TargetSize[0] = this->TargetSize[1] = 0;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastFragmentPipeline::ReleaseGraphicsResources(vtkWindow* window)
{
  this->ReleaseTargets(window);
  for (Program* p :
    { &this->FirstHitProgram, &this->PeelProgram, &this->NearSliceProgram, &this->TraversalProgram,
      &this->CopyProgram, &this->CountProgram, &this->CompositeProgram })
  {
    p->Release();
  }
  this->Queries.ReleaseGraphicsResources();
}

//------------------------------------------------------------------------------
void vtkTiledRayCastFragmentPipeline::MakeTiles()
{
  const int w = this->Current->Width;
  const int h = this->Current->Height;
  const int size = this->Current->TileSize > 0 ? this->Current->TileSize : std::max(w, h);
  this->Tiles.clear();
  for (int y = 0; y < h; y += size)
  {
    for (int x = 0; x < w; x += size)
    {
      Tile t;
      t.X0 = x;
      t.Y0 = y;
      t.X1 = std::min(x + size, w);
      t.Y1 = std::min(y + size, h);
      this->Tiles.push_back(t);
    }
  }
}

//------------------------------------------------------------------------------
vtkShaderProgram* vtkTiledRayCastFragmentPipeline::Use(
  vtkOpenGLRenderWindow* window, Program& program)
{
  window->GetShaderCache()->ReadyShaderProgram(program.Shader);
  return program.Shader;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastFragmentPipeline::SetTargetUniforms(vtkShaderProgram* p, int parity)
{
  p->SetUniformi("in_state", this->State[parity]->GetTextureUnit());
  p->SetUniformi("in_color", this->Color[parity]->GetTextureUnit());
  p->SetUniformi("in_entry", this->Entry[parity]->GetTextureUnit());
}

//------------------------------------------------------------------------------
void vtkTiledRayCastFragmentPipeline::DrawRectangle(
  Program& program, int x0, int y0, int x1, int y1)
{
  const float w = static_cast<float>(this->Current->Width);
  const float h = static_cast<float>(this->Current->Height);
  const float rect[4] = { 2.0f * x0 / w - 1.0f, 2.0f * y0 / h - 1.0f, 2.0f * x1 / w - 1.0f,
    2.0f * y1 / h - 1.0f };
  program.Shader->SetUniform4f("in_rectangle", rect);
  program.Shader->SetUniformf("in_rectangleDepth", RectangleDepth);
  // A screen rectangle is never culled: the boundary passes cull by the volume's handedness,
  // front faces (counter-clockwise, like the rectangle) when its matrix mirrors.
  this->Current->Window->GetState()->vtkglDisable(GL_CULL_FACE);
  program.VAO->Bind();
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

//------------------------------------------------------------------------------
void vtkTiledRayCastFragmentPipeline::DrawViewport(Program& program)
{
  this->DrawRectangle(program, 0, 0, this->Current->Width, this->Current->Height);
}

//------------------------------------------------------------------------------
void vtkTiledRayCastFragmentPipeline::BindTargets(vtkOpenGLState*, int parity)
{
  // Every pass writes all three targets (state, colour, entry). VTK 9.1's state cache keeps one
  // set of draw buffers for all framebuffers, so after switching framebuffers it may believe
  // ours are already set when they are not: going through "none" forces the real call.
  vtkOpenGLFramebufferObject* fbo = this->Framebuffer[parity];
  fbo->Bind(GL_DRAW_FRAMEBUFFER);
  fbo->DeactivateDrawBuffers();
  fbo->ActivateDrawBuffers(3);
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastFragmentPipeline::RenderFirstHit(vtkOpenGLRenderWindow* window)
{
  vtkTiledRayCastDebugEvent event("FirstHit");
  vtkOpenGLState* state = window->GetState();

  // Both target sets start as "no ray" (all zero), so that a tile the GPU skips because it has
  // no ray is the same in both, whatever its parity.
  state->vtkglClearColor(0.f, 0.f, 0.f, 0.f);
  state->vtkglClearDepth(1.0);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  for (int q = 1; q >= 0; --q)
  {
    this->BindTargets(state, q);
    state->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }
  this->BindTargets(state, 0);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_LESS);

  if (this->Current->NearPlaneCutsMesh)
  {
    // The camera may be inside the mesh: rays whose near-plane point lies in a tet start there.
    state->vtkglDisable(GL_CULL_FACE);
    this->Setup->SetFrameUniforms(this->Use(window, this->NearSliceProgram));
    this->Setup->SetMeshUniforms(this->NearSliceProgram.Shader);
    this->NearSliceProgram.VAO->Bind();
    this->NearPlaneQuery = this->Queries.Begin();
    glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(this->Current->NumberOfTetrahedra));
    this->Queries.End();
  }

  // Front faces are counter-clockwise seen from outside, unless the volume's matrix mirrors.
  state->vtkglEnable(GL_CULL_FACE);
  state->vtkglCullFace(this->Current->Mirrored ? GL_FRONT : GL_BACK);
  this->Setup->SetFrameUniforms(this->Use(window, this->FirstHitProgram));
  this->Setup->SetMeshUniforms(this->FirstHitProgram.Shader);
  this->Setup->SetCoverageUniforms(this->FirstHitProgram.Shader);
  this->FirstHitProgram.VAO->Bind();
  // Faces are not clipped at the near plane: their fragment shader decides there.
  const bool clamped = vtkTiledRayCastComputeShader::SetDepthClamp(true);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(3 * this->Current->NumberOfBoundaryFaces));
  vtkTiledRayCastComputeShader::SetDepthClamp(clamped);
  vtkFragmentPipelineCheckErrorMacro("failed after the first-hit pass");
  return true;
}

//------------------------------------------------------------------------------
unsigned int vtkTiledRayCastFragmentPipeline::Peel(vtkOpenGLRenderWindow* window)
{
  vtkTiledRayCastDebugEvent event("Peel");
  vtkOpenGLState* state = window->GetState();

  // The peel reads set 0 and writes set 1 where a ray re-enters: make both sets hold the same
  // state first (per tile, from whichever set is current).
  this->MakeTilesIdentical(window);

  this->BindTargets(state, 1);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglClearDepth(1.0);
  state->vtkglClear(GL_DEPTH_BUFFER_BIT);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_LESS);
  state->vtkglEnable(GL_CULL_FACE);
  state->vtkglCullFace(this->Current->Mirrored ? GL_FRONT : GL_BACK);
  vtkShaderProgram* p = this->Use(window, this->PeelProgram);
  this->Setup->SetFrameUniforms(p);
  this->Setup->SetMeshUniforms(p);
  this->Setup->SetCoverageUniforms(p);
  p->SetUniformi("in_previousState", this->State[0]->GetTextureUnit());
  p->SetUniformi("in_previousEntry", this->Entry[0]->GetTextureUnit());
  p->SetUniformi("in_previousColor", this->Color[0]->GetTextureUnit());
  p->SetUniformf("in_peelEpsilon", this->Current->PeelEpsilon);
  this->PeelProgram.VAO->Bind();
  const unsigned int query = this->Queries.Begin();
  const bool clamped = vtkTiledRayCastComputeShader::SetDepthClamp(true);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(3 * this->Current->NumberOfBoundaryFaces));
  vtkTiledRayCastComputeShader::SetDepthClamp(clamped);
  this->Queries.End();
  // Whether another layer exists decides what to draw next: this read waits for the GPU, once
  // per layer (as VTK's dual depth peeling does).
  const unsigned int reentered = this->Queries.GetResult(query);
  for (Tile& tile : this->Tiles)
  {
    tile.Parity = 1;
  }
  vtkFragmentPipelineCheckErrorMacro("failed after a peeling pass");
  return reentered;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastFragmentPipeline::CopyTile(
  vtkOpenGLRenderWindow* window, Tile& tile, bool markInactive)
{
  // Copies the tile's current set to the other set and flips its parity. As a Z-update it also
  // writes depth 0 for rays that are no longer active (later passes skip them) and 1 for the
  // others; the caller sets the depth test.
  vtkShaderProgram* copy = this->Use(window, this->CopyProgram);
  this->BindTargets(window->GetState(), 1 - tile.Parity);
  this->SetTargetUniforms(copy, tile.Parity);
  copy->SetUniformi("in_markInactive", markInactive ? 1 : 0);
  this->DrawRectangle(this->CopyProgram, tile.X0, tile.Y0, tile.X1, tile.Y1);
  tile.Parity = 1 - tile.Parity;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastFragmentPipeline::MakeTilesIdentical(vtkOpenGLRenderWindow* window)
{
  // After a copy from the current set to the other, both sets hold the same state.
  vtkOpenGLState* state = window->GetState();
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_FALSE);
  for (Tile& tile : this->Tiles)
  {
    this->CopyTile(window, tile, false);
  }
}

//------------------------------------------------------------------------------
void vtkTiledRayCastFragmentPipeline::CountActiveRays(vtkOpenGLRenderWindow* window, Tile& tile)
{
  vtkOpenGLState* state = window->GetState();
  vtkShaderProgram* count = this->Use(window, this->CountProgram);
  count->SetUniformi("in_statusMask", 1 << StatusActive);
  this->SetTargetUniforms(count, tile.Parity);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_FALSE);
  state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  tile.LastQuery = this->Queries.Begin();
  this->DrawRectangle(this->CountProgram, tile.X0, tile.Y0, tile.X1, tile.Y1);
  this->Queries.End();
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  vtkTiledRayCastStatistics* stats = this->Stats;
  stats->SetNumberOfOcclusionQueries(stats->GetNumberOfOcclusionQueries() + 1);
}

//------------------------------------------------------------------------------
void vtkTiledRayCastFragmentPipeline::RayCastLayer(vtkOpenGLRenderWindow* window)
{
  vtkTiledRayCastDebugEvent event("RayCastLayer");
  vtkOpenGLState* state = window->GetState();
  vtkObject* self = this->Current->Reporter;
  vtkTiledRayCastStatistics* stats = this->Stats;
  const int tetsPerPass = this->Current->TetsPerPass;
  const int interval = this->Current->OcclusionQueryInterval;
  const int maxPasses = this->Current->MaximumPassesPerLayer;

  // No ray of this layer is marked finished yet.
  this->BindTargets(state, 0);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglClearDepth(1.0);
  state->vtkglClear(GL_DEPTH_BUFFER_BIT);

  // Count the active rays of every tile. The GPU skips the passes of a tile whose count is zero
  // (conditional rendering), and the CPU never waits for these counts.
  for (Tile& tile : this->Tiles)
  {
    tile.PreviousQuery = 0;
    this->CountActiveRays(window, tile);
    tile.Running = true;
  }

  vtkShaderProgram* traversal = this->Use(window, this->TraversalProgram);
  this->Setup->SetFrameUniforms(traversal);
  this->Setup->SetMeshUniforms(traversal);
  this->Setup->SetIntegrationUniforms(traversal);
  traversal->SetUniformi("in_tetsPerPass", tetsPerPass);
  traversal->SetUniformi("in_maximumSteps", this->Current->MaximumSteps);

  if (tetsPerPass == 0)
  {
    // No limit on tets per pass: one pass per tile finishes every ray of the layer.
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDepthMask(GL_FALSE);
    for (size_t i = 0; i < this->Tiles.size(); ++i)
    {
      Tile& tile = this->Tiles[i];
      this->Queries.BeginConditionalRender(tile.LastQuery);
      this->BindTargets(state, 1 - tile.Parity);
      this->SetTargetUniforms(traversal, tile.Parity);
      this->DrawRectangle(this->TraversalProgram, tile.X0, tile.Y0, tile.X1, tile.Y1);
      this->Queries.EndConditionalRender();
      tile.Parity = 1 - tile.Parity;
      this->PassBlocks.push_back({ i, tile.LastQuery, 1 });
    }
    return;
  }

  // The paper's scheme: rounds of k passes per running tile, each ending with a Z-update (the
  // rays no longer active are marked in the depth buffer, so later passes skip them) and an
  // occlusion query counting the tile's active rays. A tile stops once a count of zero comes
  // back. Counts are polled without waiting; the passes issued meanwhile for a tile that is in
  // fact done are skipped by the GPU, which also leaves both of its target sets identical.
  bool anyRunning = true;
  while (anyRunning)
  {
    anyRunning = false;
    for (size_t i = 0; i < this->Tiles.size(); ++i)
    {
      Tile& tile = this->Tiles[i];
      if (!tile.Running)
      {
        continue;
      }
      // Stop once a count of zero is known. The latest count is polled; if it is not there yet,
      // the one of the round before (issued a whole round of other tiles ago) is waited for, so
      // at most one round is issued that the GPU may skip.
      if (this->Queries.IsAvailable(tile.LastQuery))
      {
        if (this->Queries.GetResult(tile.LastQuery) == 0)
        {
          tile.Running = false;
          continue;
        }
      }
      else if (tile.PreviousQuery && this->Queries.GetResult(tile.PreviousQuery) == 0)
      {
        tile.Running = false;
        continue;
      }
      if (tile.Passes >= maxPasses)
      {
        vtkWarningWithObjectMacro(self, << "A tile reached " << maxPasses
                                        << " ray-casting passes in one layer and was stopped; "
                                           "the mesh's neighbour links may loop.");
        tile.Running = false;
        continue;
      }
      anyRunning = true;
      this->Queries.BeginConditionalRender(tile.LastQuery);
      this->Use(window, this->TraversalProgram);
      state->vtkglEnable(GL_DEPTH_TEST);
      state->vtkglDepthFunc(GL_LESS);
      state->vtkglDepthMask(GL_FALSE);
      for (int k = 0; k < interval; ++k)
      {
        this->BindTargets(state, 1 - tile.Parity);
        this->SetTargetUniforms(traversal, tile.Parity);
        this->DrawRectangle(this->TraversalProgram, tile.X0, tile.Y0, tile.X1, tile.Y1);
        tile.Parity = 1 - tile.Parity;
      }
      // The Z-update writes its own depth (0 or 1) for every pixel: it must not be depth-tested
      // against the last one, or active rays (1 against 1) would not be copied and the next
      // round would start from a stale set (a lost pass per round, no progress at all for K=1).
      state->vtkglDepthFunc(GL_ALWAYS);
      state->vtkglDepthMask(GL_TRUE);
      this->CopyTile(window, tile, true);
      this->Queries.EndConditionalRender();
      this->PassBlocks.push_back({ i, tile.LastQuery, interval });
      stats->SetNumberOfZUpdatePasses(stats->GetNumberOfZUpdatePasses() + 1);
      tile.Passes += interval;
      tile.PreviousQuery = tile.LastQuery;
      this->CountActiveRays(window, tile);
    }
  }
}

//------------------------------------------------------------------------------
void vtkTiledRayCastFragmentPipeline::Composite(vtkOpenGLRenderWindow* window)
{
  vtkTiledRayCastDebugEvent event("Composite");
  vtkOpenGLState* state = window->GetState();
  vtkTiledRayCastStatistics* stats = this->Stats;

  // Bring every tile to set 0, then count the rays that became opaque.
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_FALSE);
  for (Tile& tile : this->Tiles)
  {
    if (tile.Parity == 1)
    {
      this->CopyTile(window, tile, false);
    }
  }
  vtkShaderProgram* count = this->Use(window, this->CountProgram);
  count->SetUniformi("in_statusMask", 1 << StatusDoneOpaque);
  this->SetTargetUniforms(count, 0);
  state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  const unsigned int opaqueQuery = this->Queries.Begin();
  this->DrawViewport(this->CountProgram);
  this->Queries.End();
  // And the rays that entered the mesh, counted here rather than while compositing: the
  // caller's framebuffer may be multisampled, ours counts pixels.
  count->SetUniformi("in_statusMask", ~(1 << StatusMiss));
  const unsigned int raysQuery = this->Queries.Begin();
  this->DrawViewport(this->CountProgram);
  this->Queries.End();
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

  // Back to the caller's framebuffer and viewport: blend the premultiplied colour over it.
  state->PopFramebufferBindings();
  const int* viewport = this->Current->Viewport;
  state->vtkglViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  vtkShaderProgram* composite = this->Use(window, this->CompositeProgram);
  this->SetTargetUniforms(composite, 0);
  const float origin[2] = { static_cast<float>(viewport[0]), static_cast<float>(viewport[1]) };
  composite->SetUniform2f("in_viewportOrigin", origin);
  this->Setup->SetSampleScaleUniforms(composite);
  this->DrawViewport(this->CompositeProgram);

  stats->SetNumberOfRaysTerminatedEarly(this->Queries.GetResult(opaqueQuery));
  stats->SetNumberOfRays(this->Queries.GetResult(raysQuery));
  vtkFragmentPipelineCheckErrorMacro("failed after compositing");
}

//------------------------------------------------------------------------------
void vtkTiledRayCastFragmentPipeline::FinishStatistics()
{
  // Passes the GPU really ran: those whose tile count was not zero (all these queries are
  // answered by now, the last peel having waited for the GPU).
  vtkTiledRayCastStatistics* stats = this->Stats;
  std::vector<int> passes(this->Tiles.size(), 0);
  vtkIdType total = 0;
  for (const PassBlock& block : this->PassBlocks)
  {
    if (this->Queries.GetResult(block.Condition) > 0)
    {
      passes[block.TileIndex] += block.Passes;
      total += block.Passes;
    }
  }
  std::vector<int>& perTile = stats->GetPassesPerTile();
  perTile.clear();
  int skipped = 0;
  for (int p : passes)
  {
    if (p > 0)
    {
      perTile.push_back(p);
    }
    else
    {
      ++skipped;
    }
  }
  stats->FinishTilePasses();
  stats->SetNumberOfRayCastPasses(total);
  stats->SetNumberOfNearPlaneRays(
    this->NearPlaneQuery ? this->Queries.GetResult(this->NearPlaneQuery) : 0);
  stats->SetNumberOfTiles(static_cast<int>(this->Tiles.size()));
  stats->SetNumberOfTilesSkipped(skipped);
}
