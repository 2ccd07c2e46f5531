/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastComputePipeline.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastComputePipeline.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTiledRayCastComputeShader.h"
#include "vtkTiledRayCastDebugEvent.h"
#include "vtkTiledRayCastPeelAccumulation.h"
#include "vtkTiledRayCastPhaseTimers.h"
#include "vtkTiledRayCastStatistics.h"
#include "vtkTiledRayCastVolumetricPeel.h"
#include "vtk_glew.h"

#include "vtkTiledRayCastBoundaryFaceFS.h"
#include "vtkTiledRayCastBoundaryFaceVS.h"
#include "vtkTiledRayCastCompositeFS.h"
#include "vtkTiledRayCastEntryList.h"
#include "vtkTiledRayCastNearSliceFS.h"
#include "vtkTiledRayCastNearSliceGS.h"
#include "vtkTiledRayCastNearSliceVS.h"
#include "vtkTiledRayCastQuadVS.h"
#include "vtkTiledRayCastTraversalCS.h"
#include "vtkTiledRayCastTraversalTile.h"
#include "vtkTiledRayCastWalk.h"

#include <algorithm>
#include <cstdint>

namespace
{
// Image units and storage-buffer binding points, as declared in the GLSL.
const unsigned int HeadsImageUnit = 0;
const unsigned int ColorImageUnit = 1;
const unsigned int BackColorImageUnit = 3; // taking part in VTK's dual depth peeling
const unsigned int NodesBinding = 0;
const unsigned int EntryCountBinding = 1;
const unsigned int RayCountsBinding = 2;
// The traversal's workgroup size in pixels (local_size_x and local_size_y of
// vtkTiledRayCastTraversalTile.glsl). An entry node is 3 words (lambda, key, link), 4 in a group
// of overlapping volumes (and the volume).
const int GroupWidth = 8;
const int GroupHeight = 4;

// The counts of trcRayCountBuffer (vtkTiledRayCastTraversalTile.glsl), in order.
enum RayCount
{
  CountRays = 0,
  CountNearPlaneRays,
  CountTerminatedEarly,
  CountMaximumLayers,
  CountStepsLow,
  CountStepsHigh,
  CountMaximumSteps,
  CountStopped,
  CountEmptyGroups,
  CountIncomplete,
  CountEntriesAsked, // copied from the entry count after the traversal
  CountMixedRays,    // rays through overlapping volumes' mixtures (groups only)
  NumberOfRayCounts
};

} // anonymous namespace

//------------------------------------------------------------------------------
std::string vtkTiledRayCastComputePipeline::Substituted(
  std::string source, const Replacements& replacements)
{
  for (const auto& r : replacements)
  {
    vtkShaderProgram::Substitute(source, r.first, r.second, true);
  }
  return source;
}

//------------------------------------------------------------------------------
vtkTiledRayCastComputePipeline::vtkTiledRayCastComputePipeline() = default;

//------------------------------------------------------------------------------
vtkTiledRayCastComputePipeline::~vtkTiledRayCastComputePipeline() = default;

//------------------------------------------------------------------------------
bool vtkTiledRayCastComputePipeline::Render(const Frame& frame, vtkTiledRayCastProgramSetup& setup,
  vtkTiledRayCastPhaseTimers& timers, vtkTiledRayCastStatistics* stats, std::string& error)
{
  vtkOpenGLState* state = frame.Window->GetState();
  // A later stage of VTK's depth peeling traverses the entries the volume's first stage listed.
  const bool reuse = frame.PeelStage >= 2 && frame.PeelVolume &&
    frame.PeelVolume == this->EntriesKeptFor && frame.Members.size() == this->EntriesKeptMembers;
  if (!this->BeginFrame(frame, reuse, stats, error))
  {
    state->PopFramebufferBindings();
    return false;
  }
  if (!reuse)
  {
    vtkTiledRayCastDebugEvent event("ListEntries");
    timers.Start(vtkTiledRayCastPhaseTimers::FirstHit);
    this->ListEntries(frame, setup);
    timers.Stop(vtkTiledRayCastPhaseTimers::FirstHit);
  }
  {
    vtkTiledRayCastDebugEvent event("Traverse");
    timers.Start(vtkTiledRayCastPhaseTimers::RayCasting);
    this->Traverse(frame, setup);
    timers.Stop(vtkTiledRayCastPhaseTimers::RayCasting);
  }
  const bool ok = this->FinishEntries(frame, setup, stats, error);

  // Back to the caller's framebuffer and viewport: blend the premultiplied colour over it.
  state->PopFramebufferBindings();
  if (!ok)
  {
    return false;
  }
  if (frame.Accumulation)
  {
    // One of several sets of volumes in a stage of VTK's depth peeling: over the sets behind.
    frame.Accumulation->Add(frame.Window, this->Color, this->BackColor);
  }
  else
  {
    vtkTiledRayCastDebugEvent event("Composite");
    timers.Start(vtkTiledRayCastPhaseTimers::Compositing);
    const int* viewport = frame.Viewport;
    state->vtkglViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    this->Composite(frame, setup);
    timers.Stop(vtkTiledRayCastPhaseTimers::Compositing);
  }

  stats->SetDepthPeelingEntriesReused(reuse);
  stats->SetNumberOfTiles(vtkTiledRayCastComputePipeline::GetNumberOfTiles(frame));
  stats->SetNumberOfRayCastPasses(1);
  stats->GetPassesPerTile().clear();
  stats->FinishTilePasses();
  return true;
}

//------------------------------------------------------------------------------
int vtkTiledRayCastComputePipeline::GetNumberOfTiles(const Frame& frame)
{
  return ((frame.Width + GroupWidth - 1) / GroupWidth) *
    ((frame.Height + GroupHeight - 1) / GroupHeight);
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkTiledRayCastComputePipeline::GetColorTexture()
{
  return this->Color;
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastComputePipeline::ReadyRaster(vtkOpenGLRenderWindow* window,
  RasterProgram& program, const std::string& vs, const std::string& fs, const std::string& gs,
  std::string& error)
{
  const std::string key = vs + fs + gs;
  if (key == program.Key && program.Shader)
  {
    return true;
  }
  vtkShaderProgram* shader =
    window->GetShaderCache()->ReadyShaderProgram(vs.c_str(), fs.c_str(), gs.c_str());
  if (!shader || !shader->GetCompiled())
  {
    error = "A shader of the tiled ray caster's compute pipeline failed to compile or link; see "
            "the shader log above. Nothing is drawn.";
    program.Shader = nullptr;
    return false;
  }
  if (shader != program.Shader)
  {
    program.Shader = shader;
    program.VAO->ShaderProgramChanged();
  }
  program.Key = key;
  return true;
}

//------------------------------------------------------------------------------
vtkTiledRayCastComputePipeline::Replacements vtkTiledRayCastComputePipeline::ProgramReplacements(
  const Replacements& common, bool group)
{
  // Every program of this pipeline is GLSL 4.30 with the entry list in place of the fragment
  // pipeline's render-target outputs; a group's entries say whose they are.
  Replacements replacements = common;
  replacements.emplace_back("//TRC::Version",
    group ? "#version 430 core\n#define TRC_ENTRY_LIST\n#define TRC_GROUP_ENTRIES\n"
          : "#version 430 core\n#define TRC_ENTRY_LIST\n");
  replacements.emplace_back("//TRC::EntryList::Dec", vtkTiledRayCastEntryList);
  replacements.emplace_back("//TRC::EntryTarget::Dec", vtkTiledRayCastEntryList);
  replacements.emplace_back("//TRC::TraversalTile::Dec", vtkTiledRayCastTraversalTile);
  replacements.emplace_back("//TRC::Walk::Dec", vtkTiledRayCastWalk);
  for (const char* tag : { "//TRC::Peel::Dec", "//TRC::Peel::Early", "//TRC::Peel::Impl" })
  {
    replacements.emplace_back(tag, std::string());
  }
  return replacements;
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastComputePipeline::UpdatePrograms(
  vtkOpenGLRenderWindow* window, const Replacements& common, std::string& error)
{
  // The programs of VTK's depth peeling stages are built from the same pieces, when needed.
  this->PeelCommon = common;
  for (PeelPrograms& peel : this->Peel)
  {
    peel.Built = false;
  }
  const Replacements replacements = ProgramReplacements(common, false);
  const std::string faceVS = Substituted(vtkTiledRayCastBoundaryFaceVS, replacements);
  if (!this->ReadyRaster(window, this->FacesProgram, faceVS,
        Substituted(vtkTiledRayCastBoundaryFaceFS, replacements), std::string(), error) ||
    !this->ReadyRaster(window, this->NearSliceProgram,
      Substituted(vtkTiledRayCastNearSliceVS, replacements),
      Substituted(vtkTiledRayCastNearSliceFS, replacements),
      Substituted(vtkTiledRayCastNearSliceGS, replacements), error) ||
    !this->ReadyRaster(window, this->CompositeProgram,
      Substituted(vtkTiledRayCastQuadVS, replacements),
      Substituted(vtkTiledRayCastCompositeFS, replacements), std::string(), error))
  {
    return false;
  }
  vtkTiledRayCastComputeShader* shader = this->Traversal;
  const std::string source = Substituted(vtkTiledRayCastTraversalCS, replacements);
  if ((source != shader->GetSource() || !shader->GetHandle()) && !shader->Build(source))
  {
    error = "The compute shader of the tiled ray caster failed to build (" + shader->GetError() +
      "). Nothing is drawn.";
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastComputePipeline::UpdateTargets(
  vtkOpenGLRenderWindow* window, int width, int height, std::string& error)
{
  if (width <= this->TargetSize[0] && height <= this->TargetSize[1] &&
    this->Framebuffer->GetFBOIndex() != 0)
  {
    return true;
  }
  width = std::max(width, this->TargetSize[0]);
  height = std::max(height, this->TargetSize[1]);
  // The list heads start at zero (no entry) and the traversal leaves them so: they are
  // cleared here, at allocation, and again only after the draws of VTK's depth peeling, which
  // keep them for the next draw (ListEntries).
  const std::vector<std::uint32_t> zeros(static_cast<size_t>(width) * height, 0u);
  vtkTextureObject* heads = this->EntryHeads;
  heads->ReleaseGraphicsResources(window);
  heads->SetContext(window);
  heads->SetInternalFormat(GL_R32UI);
  heads->SetFormat(GL_RED_INTEGER);
  heads->SetDataType(GL_UNSIGNED_INT);
  heads->SetMinificationFilter(vtkTextureObject::Nearest);
  heads->SetMagnificationFilter(vtkTextureObject::Nearest);
  bool ok = heads->Create2DFromRaw(
    width, height, 1, VTK_UNSIGNED_INT, const_cast<std::uint32_t*>(zeros.data()));
  vtkTextureObject* color = this->Color;
  color->SetContext(window);
  color->SetInternalFormat(GL_RGBA16);
  color->SetFormat(GL_RGBA);
  color->SetDataType(GL_UNSIGNED_SHORT);
  color->SetMinificationFilter(vtkTextureObject::Nearest);
  color->SetMagnificationFilter(vtkTextureObject::Nearest);
  color->SetWrapS(vtkTextureObject::ClampToEdge);
  color->SetWrapT(vtkTextureObject::ClampToEdge);
  if (color->GetHandle() && color->GetWidth() > 0)
  {
    color->Resize(width, height);
  }
  else
  {
    ok = ok && color->Allocate2D(width, height, 4, VTK_UNSIGNED_SHORT);
  }
  if (this->BackColor->GetHandle())
  {
    this->BackColor->Resize(width, height);
  }
  // One entry per pixel to start with; the list grows to what views need (ListEntries).
  ok = ok && this->GrowEntries(static_cast<vtkIdType>(width) * height, error);
  ok = ok && this->EntryCount.Allocate(sizeof(std::uint32_t));
  for (int i = 0; i < 2; ++i)
  {
    ok = ok && this->RayCounts[i].Allocate(NumberOfRayCounts * sizeof(std::uint32_t));
    ok = ok && this->CountsRead[i].AllocateForReading(NumberOfRayCounts * sizeof(std::uint32_t));
  }
  if (!ok)
  {
    if (error.empty())
    {
      error = "Cannot allocate the compute pipeline's per-pixel buffers. Nothing is drawn.";
    }
    return false;
  }
  // The entry pass draws into this framebuffer with colour writes off: it only sets the size
  // of the raster.
  vtkOpenGLState* state = window->GetState();
  state->PushFramebufferBindings();
  vtkOpenGLFramebufferObject* fbo = this->Framebuffer;
  fbo->SetContext(window);
  fbo->Bind();
  fbo->AddColorAttachment(0, color);
  fbo->ActivateDrawBuffers(1);
  ok = fbo->CheckFrameBufferStatus(GL_FRAMEBUFFER) != 0;
  state->PopFramebufferBindings();
  if (!ok)
  {
    error = "The compute pipeline's framebuffer is incomplete on this GPU. Nothing is drawn.";
    return false;
  }
  this->TargetSize[0] = width;
  this->TargetSize[1] = height;
  this->EntriesKeptFor = nullptr; // new heads, zeros
  this->CountsPending[0] = this->CountsPending[1] = false;
  this->Verified = false;
  return true;
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastComputePipeline::GrowEntries(vtkIdType needed, std::string& error)
{
  if (needed <= this->EntryCapacity)
  {
    return true;
  }
  // A quarter more than asked, so that a slowly changing view does not grow it every frame.
  vtkIdType capacity = needed + needed / 4 + 4096;
  const vtkIdType limit = 0x7FFFFFFF; // node indices + 1 fit in 31 bits (TRC_ENTRY_NODE)
  if (needed > limit)
  {
    error = "The view needs more ray entries (" + std::to_string(needed) +
      ") than the compute pipeline can list (2^31). Nothing is drawn.";
    return false;
  }
  capacity = std::min(capacity, limit);
  if (!this->EntryNodes.Allocate(static_cast<size_t>(capacity * this->EntryWords * 4)))
  {
    this->EntryCapacity = 0;
    error = "The GPU ran out of memory for the list of ray entries (" + std::to_string(needed) +
      " entries of " + std::to_string(4 * this->EntryWords) + " bytes). Nothing is drawn.";
    return false;
  }
  this->EntryCapacity = capacity;
  return true;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastComputePipeline::BindBuffers()
{
  vtkTiledRayCastComputeShader::BindImage(
    HeadsImageUnit, this->EntryHeads, GL_READ_WRITE, GL_R32UI);
  vtkTiledRayCastComputeShader::BindImage(ColorImageUnit, this->Color, GL_WRITE_ONLY, GL_RGBA16);
  this->EntryNodes.BindBase(NodesBinding);
  this->EntryCount.BindBase(EntryCountBinding);
  this->RayCounts[this->CountsBuffer].BindBase(RayCountsBinding);
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastComputePipeline::BeginFrame(
  const Frame& frame, bool reuse, vtkTiledRayCastStatistics* stats, std::string& error)
{
  // The previous frame's counts if they have arrived, else the older ones in the other buffer
  // (waiting for them holds the CPU at most two frames ahead of the GPU), which this frame
  // then writes over.
  const int last = this->CountsBuffer;
  const int next = 1 - last;
  bool read = false;
  if (this->CountsPending[last] && this->CountsRead[last].IsWritten(false))
  {
    this->ReadCountsInto(last, stats);
    read = true;
  }
  if (this->CountsPending[next])
  {
    if (read)
    {
      this->CountsPending[next] = false; // older than what was just read
    }
    else
    {
      this->CountsRead[next].IsWritten(true);
      this->ReadCountsInto(next, stats);
    }
  }
  this->CountsBuffer = next;
  // The latest counts read, also when none came since (the frame before was verified and read
  // its own): the statistics show those, as they keep the latest GPU times, rather than zeros.
  this->ReportCounts(stats);

  if (reuse)
  {
    this->Verifying = false; // the list holds this view: the first stage saw to it
    return true;
  }
  // A group's list has a fourth word per entry: the list is allocated again when that changes.
  const vtkIdType words = frame.Members.empty() ? 3 : 4;
  if (words != this->EntryWords)
  {
    this->EntryWords = words;
    this->EntryCapacity = 0;
    if (!this->GrowEntries(static_cast<vtkIdType>(frame.Width) * frame.Height, error))
    {
      return false;
    }
  }
  // A frame is verified (its counts read before Render() returns, the list grown and the
  // frame drawn again if it did not hold the view) when asked, when nothing is known yet of
  // what this mesh asks for at this image size, and on a camera jump: the bounds cover a
  // quarter more of the view than in the last frame, or the view turned by more than 30
  // degrees (more boundary layers may face it). Frames of a camera that moves (interaction,
  // animation) are not verified: their entry counts change by little from one frame to the
  // next, which the list's headroom absorbs.
  const float* d = frame.ViewDirection;
  const float turn =
    d[0] * this->LastDirection[0] + d[1] * this->LastDirection[1] + d[2] * this->LastDirection[2];
  const bool jump = turn < 0.866f || frame.BoundsCoverage > 1.25 * this->LastCoverage + 1e-3;
  this->Verifying = frame.Verify || !this->Verified || jump ||
    frame.NumberOfBoundaryFaces != this->ListedFaces ||
    frame.NumberOfTetrahedra != this->ListedTetrahedra;
  this->ListedFaces = frame.NumberOfBoundaryFaces;
  this->ListedTetrahedra = frame.NumberOfTetrahedra;
  std::copy(d, d + 3, this->LastDirection);
  this->LastCoverage = frame.BoundsCoverage;
  // A quarter to spare over what the latest view counted asked for (GrowEntries adds another),
  // and room for its mean entries per ray at every pixel, up to two (24 B a pixel): a camera
  // that comes closer then finds room for meshes of one or two boundary layers.
  const double perRay = this->RaysCounted > 0
    ? std::min(2.0, static_cast<double>(this->EntriesAsked) / this->RaysCounted)
    : 0.0;
  const vtkIdType wanted = std::max(this->EntriesAsked + this->EntriesAsked / 4,
    static_cast<vtkIdType>(perRay * frame.Width * frame.Height));
  return this->GrowEntries(wanted, error);
}

//------------------------------------------------------------------------------
void vtkTiledRayCastComputePipeline::ListEntries(
  const Frame& frame, vtkTiledRayCastProgramSetup& setup)
{
  vtkOpenGLState* state = frame.Window->GetState();
  state->PushDrawFramebufferBinding();
  this->Framebuffer->Bind(GL_DRAW_FRAMEBUFFER);
  vtkOpenGLState::ScopedglColorMask colorMask(state);
  state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_FALSE);

  if (this->EntriesKeptFor)
  {
    // The last traversal (a stage of VTK's depth peeling) left the heads for the next draw.
    vtkTiledRayCastComputeShader::ClearImage(this->EntryHeads);
    vtkTiledRayCastComputeShader::Barrier(
      GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    this->EntriesKeptFor = nullptr;
  }
  this->EntryCount.Write(0, sizeof(std::uint32_t));
  this->BindBuffers();
  if (frame.Members.empty())
  {
    Member alone;
    alone.NumberOfBoundaryFaces = frame.NumberOfBoundaryFaces;
    alone.NumberOfTetrahedra = frame.NumberOfTetrahedra;
    alone.NearPlaneCutsMesh = frame.NearPlaneCutsMesh;
    alone.Mirrored = frame.Mirrored;
    this->ListMemberEntries(
      frame, alone, this->FacesProgram, this->NearSliceProgram, setup, false, 0);
  }
  for (size_t k = 0; k < frame.Members.size(); ++k)
  {
    const Member& member = frame.Members[k];
    this->ListMemberEntries(
      frame, member, this->GroupFaces[k], this->GroupSlices[k], *member.Setup, true, int(k));
  }
  vtkTiledRayCastComputeShader::Barrier(GL_BUFFER_UPDATE_BARRIER_BIT |
    GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  state->PopDrawFramebufferBinding();
}

//------------------------------------------------------------------------------
void vtkTiledRayCastComputePipeline::ListMemberEntries(const Frame& frame, const Member& member,
  RasterProgram& faces, RasterProgram& slices, vtkTiledRayCastProgramSetup& setup, bool group,
  int index)
{
  vtkOpenGLState* state = frame.Window->GetState();
  vtkOpenGLShaderCache* cache = frame.Window->GetShaderCache();
  const int capacity = static_cast<int>(this->EntryCapacity);
  // What both raster programs take: a group's volumes list their entries into one list, each
  // under its index, against the scene's depth the first volume holds (another volume's own
  // scene-depth texture is not active in a group's frame).
  // A group's volumes' boundary faces are active only for their own listing.
  if (group)
  {
    setup.ActivateEntryTextures(true);
  }
  auto setUniforms = [&](vtkShaderProgram* p)
  {
    setup.SetFrameUniforms(p);
    setup.SetMeshUniforms(p);
    p->SetUniformi("in_entryCapacity", capacity);
    if (group)
    {
      p->SetUniformi("in_groupMember", index);
      p->SetUniformi("in_opaqueDepth", frame.OpaqueDepthUnit);
    }
  };
  if (member.NearPlaneCutsMesh)
  {
    // The camera may be inside the mesh: rays whose near-plane point lies in a tet start there.
    state->vtkglDisable(GL_CULL_FACE);
    cache->ReadyShaderProgram(slices.Shader);
    setUniforms(slices.Shader);
    slices.VAO->Bind();
    glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(member.NumberOfTetrahedra));
  }
  // Front faces are counter-clockwise seen from outside, unless the volume's matrix mirrors.
  state->vtkglEnable(GL_CULL_FACE);
  state->vtkglCullFace(member.Mirrored ? GL_FRONT : GL_BACK);
  cache->ReadyShaderProgram(faces.Shader);
  setUniforms(faces.Shader);
  setup.SetCoverageUniforms(faces.Shader);
  faces.VAO->Bind();
  const bool clamped = vtkTiledRayCastComputeShader::SetDepthClamp(true);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(3 * member.NumberOfBoundaryFaces));
  vtkTiledRayCastComputeShader::SetDepthClamp(clamped);
  if (group)
  {
    setup.ActivateEntryTextures(false);
  }
}

//------------------------------------------------------------------------------
void vtkTiledRayCastComputePipeline::Traverse(
  const Frame& frame, vtkTiledRayCastProgramSetup& setup)
{
  vtkTiledRayCastStorageBuffer& counts = this->RayCounts[this->CountsBuffer];
  counts.Write(0, NumberOfRayCounts * sizeof(std::uint32_t));
  vtkTiledRayCastComputeShader* traversal = !frame.Members.empty()
    ? this->Group.GetProgram(frame.PeelStage)
    : frame.PeelStage > 0 ? this->Peel[frame.PeelStage - 1].Traversal.Get()
                          : this->Traversal.Get();
  traversal->Use(frame.Window);
  if (frame.Members.empty())
  {
    setup.SetFrameUniforms(traversal);
    setup.SetMeshUniforms(traversal);
    setup.SetIntegrationUniforms(traversal);
  }
  else
  {
    this->SetGroupUniforms(frame);
  }
  if (frame.PeelStage > 0)
  {
    // The depth peeling pass's textures (vtkTiledRayCastVolumetricPeel), and the back colour.
    frame.Peel->SetUniforms(traversal);
    vtkTiledRayCastComputeShader::BindImage(
      BackColorImageUnit, this->BackColor, GL_WRITE_ONLY, GL_RGBA16);
  }
  // Inside VTK's depth peeling the heads stay for the volume's next draw, where they can be
  // cleared before another listing.
  const bool keep =
    frame.PeelStage > 0 && frame.PeelVolume && vtkTiledRayCastComputeShader::CanClearImages();
  traversal->SetUniformi("in_keepEntries", keep ? 1 : 0);
  const int size[2] = { frame.Width, frame.Height };
  traversal->SetUniform2i("in_imageSize", size);
  traversal->SetUniformi("in_maximumSteps", frame.MaximumSteps);
  traversal->SetUniformf("in_peelEpsilon", frame.PeelEpsilon);
  this->BindBuffers();
  traversal->Dispatch(
    (frame.Width + GroupWidth - 1) / GroupWidth, (frame.Height + GroupHeight - 1) / GroupHeight);
  vtkTiledRayCastComputeShader::Barrier(GL_TEXTURE_FETCH_BARRIER_BIT |
    GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT |
    GL_SHADER_STORAGE_BARRIER_BIT);
  vtkTiledRayCastComputeShader::UnbindImage(HeadsImageUnit);
  vtkTiledRayCastComputeShader::UnbindImage(ColorImageUnit);
  if (keep)
  {
    this->EntriesKeptFor = frame.PeelVolume;
    this->EntriesKeptMembers = frame.Members.size();
  }
  if (frame.PeelStage > 0)
  {
    vtkTiledRayCastComputeShader::UnbindImage(BackColorImageUnit);
  }
  // The entry count goes with the frame's counts (read with them, without waiting).
  this->EntryCount.CopyTo(
    counts, 0, CountEntriesAsked * sizeof(std::uint32_t), sizeof(std::uint32_t));
  vtkTiledRayCastStorageBuffer& read = this->CountsRead[this->CountsBuffer];
  counts.CopyTo(read, 0, 0, NumberOfRayCounts * sizeof(std::uint32_t));
  read.MarkWritten();
  this->CountsPending[this->CountsBuffer] = true;
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastComputePipeline::FinishEntries(const Frame& frame,
  vtkTiledRayCastProgramSetup& setup, vtkTiledRayCastStatistics* stats, std::string& error)
{
  if (!this->Verifying)
  {
    return true; // Render() returns without waiting: the counts arrive with a later frame
  }
  this->ReadCounts(stats);
  if (this->EntriesAsked > this->EntryCapacity)
  {
    // The list did not hold this view (the first frame of a mesh, or a camera jump): grow to
    // what it asked for and draw it again.
    if (!this->GrowEntries(this->EntriesAsked, error))
    {
      return false;
    }
    this->ListEntries(frame, setup);
    this->Traverse(frame, setup);
    this->ReadCounts(stats);
  }
  this->Verified = true;
  return true;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastComputePipeline::Composite(
  const Frame& frame, vtkTiledRayCastProgramSetup& setup)
{
  RasterProgram& program =
    frame.PeelStage > 0 ? this->Peel[frame.PeelStage - 1].Composite : this->CompositeProgram;
  frame.Window->GetShaderCache()->ReadyShaderProgram(program.Shader);
  vtkShaderProgram* p = program.Shader;
  p->SetUniformi("in_color", this->Color->GetTextureUnit());
  if (frame.PeelStage > 0)
  {
    // The peeling pass's textures, and the back colour (the caller activated the front one).
    frame.Peel->SetUniforms(p);
    this->BackColor->Activate();
    p->SetUniformi("in_backColor", this->BackColor->GetTextureUnit());
  }
  setup.SetSampleScaleUniforms(p);
  p->SetUniform2f("in_viewportOrigin", frame.ViewportOrigin);
  const float rectangle[4] = { -1.f, -1.f, 1.f, 1.f };
  p->SetUniform4f("in_rectangle", rectangle);
  p->SetUniformf("in_rectangleDepth", 0.f);
  // Never culled: the entry pass culls by the volume's handedness, front faces (counter-clockwise,
  // like this rectangle) when its matrix mirrors.
  frame.Window->GetState()->vtkglDisable(GL_CULL_FACE);
  program.VAO->Bind();
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  if (frame.PeelStage > 0)
  {
    this->BackColor->Deactivate();
  }
}

//------------------------------------------------------------------------------
void vtkTiledRayCastComputePipeline::ReadCounts(vtkTiledRayCastStatistics* stats)
{
  if (this->CountsPending[this->CountsBuffer])
  {
    this->CountsRead[this->CountsBuffer].IsWritten(true);
    this->ReadCountsInto(this->CountsBuffer, stats);
  }
}

//------------------------------------------------------------------------------
void vtkTiledRayCastComputePipeline::ReadCountsInto(int buffer, vtkTiledRayCastStatistics* stats)
{
  this->LastCounts.resize(NumberOfRayCounts);
  std::uint32_t* counts = this->LastCounts.data();
  this->CountsRead[buffer].Read(0, NumberOfRayCounts * sizeof(std::uint32_t), counts);
  this->CountsPending[buffer] = false;
  this->ReportCounts(stats);
  this->RaysStopped = counts[CountStopped];
  this->RaysIncomplete = counts[CountIncomplete];
  this->EntriesAsked = counts[CountEntriesAsked];
  this->RaysCounted = counts[CountRays];
}

//------------------------------------------------------------------------------
void vtkTiledRayCastComputePipeline::ReportCounts(vtkTiledRayCastStatistics* stats) const
{
  if (this->LastCounts.empty())
  {
    return;
  }
  const std::uint32_t* counts = this->LastCounts.data();
  stats->SetNumberOfRays(counts[CountRays]);
  stats->SetNumberOfNearPlaneRays(counts[CountNearPlaneRays]);
  stats->SetNumberOfRaysTerminatedEarly(counts[CountTerminatedEarly]);
  stats->SetNumberOfLayers(static_cast<int>(counts[CountMaximumLayers]));
  stats->SetNumberOfSteps(static_cast<vtkIdType>(
    (static_cast<std::uint64_t>(counts[CountStepsHigh]) << 32) | counts[CountStepsLow]));
  stats->SetMaximumStepsPerRay(counts[CountMaximumSteps]);
  stats->SetNumberOfTilesSkipped(static_cast<int>(counts[CountEmptyGroups]));
  stats->SetNumberOfEntries(counts[CountEntriesAsked]);
  stats->SetNumberOfIncompleteRays(counts[CountIncomplete]);
  stats->SetNumberOfMixedRays(counts[CountMixedRays]);
}

//------------------------------------------------------------------------------
vtkIdType vtkTiledRayCastComputePipeline::GetTargetBytes() const
{
  // List heads (4 B) and colour (8 B) per pixel of the targets (and the back colour, 8 B, once
  // the volume took part in depth peeling), and the entry list.
  const int backColor = this->BackColor->GetHandle() ? 8 : 0;
  return static_cast<vtkIdType>(this->TargetSize[0]) * this->TargetSize[1] * (4 + 8 + backColor) +
    this->EntryCapacity * this->EntryWords * 4;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastComputePipeline::ReleaseGraphicsResources(vtkWindow* window)
{
  for (RasterProgram* p : { &this->FacesProgram, &this->NearSliceProgram, &this->CompositeProgram })
  {
    p->Shader = nullptr;
    p->VAO->ReleaseGraphicsResources();
    p->Key.clear();
  }
  this->Traversal->ReleaseProgram();
  for (PeelPrograms& peel : this->Peel)
  {
    peel.Composite.Shader = nullptr;
    peel.Composite.VAO->ReleaseGraphicsResources();
    peel.Composite.Key.clear();
    peel.Traversal->ReleaseProgram();
    peel.Built = false;
  }
  this->BackColor->ReleaseGraphicsResources(window);
  for (int k = 0; k < vtkTiledRayCastGroupTraversal::MaximumMembers; ++k)
  {
    for (RasterProgram* p : { &this->GroupFaces[k], &this->GroupSlices[k] })
    {
      p->Shader = nullptr;
      p->VAO->ReleaseGraphicsResources();
      p->Key.clear();
    }
  }
  this->Group.ReleaseGraphicsResources();
  this->EntryHeads->ReleaseGraphicsResources(window);
  this->Color->ReleaseGraphicsResources(window);
  this->Framebuffer->ReleaseGraphicsResources(window);
  this->EntryNodes.ReleaseGraphicsResources();
  this->EntryCount.ReleaseGraphicsResources();
  for (int i = 0; i < 2; ++i)
  {
    this->RayCounts[i].ReleaseGraphicsResources();
    this->CountsRead[i].ReleaseGraphicsResources();
  }
  this->EntryCapacity = 0;
  this->EntriesAsked = 0;
  this->RaysCounted = 0;
  this->Verified = false;
  this->TargetSize[0] = this->TargetSize[1] = 0;
  this->CountsPending[0] = this->CountsPending[1] = false;
  this->LastCounts.clear();
  this->EntriesKeptFor = nullptr;
}
