/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkOpenGLTiledRayCastVolumeMapper.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkOpenGLTiledRayCastVolumeMapper.h"
#include "vtkOpenGLTiledRayCastVolumeMapperInternals.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTetMeshCompactLayout.h"
#include "vtkTextureObject.h"
#include "vtkTiledRayCastComputePipeline.h"
#include "vtkTiledRayCastComputeShader.h"
#include "vtkTiledRayCastContext.h"
#include "vtkTiledRayCastDebugEvent.h"
#include "vtkTiledRayCastFragmentPipeline.h"
#include "vtkTiledRayCastFrameGeometry.h"
#include "vtkTiledRayCastIntegration.h"
#include "vtkTiledRayCastOpaqueDepth.h"
#include "vtkTiledRayCastPhaseTimers.h"
#include "vtkTiledRayCastResourceFreeCallback.h"
#include "vtkTiledRayCastSampleDistance.h"
#include "vtkTiledRayCastShaderComposition.h"
#include "vtkTiledRayCastStatistics.h"
#include "vtkTiledRayCastTransferFunction.h"
#include "vtkTiledRayCastVolumeGroup.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGridBase.h"
#include "vtkVolume.h"
#include "vtkVolumeMapper.h"
#include "vtkVolumeProperty.h"
#include "vtk_glew.h"

#include <algorithm>
#include <string>

// vtkOpenGLCheckErrorMacro (compiled where NDEBUG is not defined) reports with vtkErrorMacro,
// which needs a vtkObject's `this`: the internals report through their mapper.
#if defined(VTK_REPORT_OPENGL_ERRORS)
#define vtkInternalsErrorMacro(x) vtkErrorWithObjectMacro(this->Self, x)
#define vtkInternalsCheckErrorMacro(message)                                                       \
  vtkOpenGLCheckErrorMacroImpl(vtkInternalsErrorMacro, message)
#else
#define vtkInternalsCheckErrorMacro(message)
#endif

vtkStandardNewMacro(vtkOpenGLTiledRayCastVolumeMapper);

namespace
{
void Activate(vtkTextureObject* texture, bool activate)
{
  if (activate)
  {
    texture->Activate();
  }
  else
  {
    texture->Deactivate();
  }
}

} // anonymous namespace

//------------------------------------------------------------------------------
bool vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::ChoosePipeline()
{
  const int requested = this->Self->GetPipeline();
  if (requested == vtkTiledRayCastVolumeMapper::COMPUTE_PIPELINE && !this->Context.ComputeSupported)
  {
    this->ReportError("The compute pipeline needs OpenGL 4.3, which this context lacks. Nothing "
                      "is drawn (the automatic or the fragment pipeline would draw).");
    return false;
  }
  const bool compute = requested == vtkTiledRayCastVolumeMapper::COMPUTE_PIPELINE ||
    (requested == vtkTiledRayCastVolumeMapper::AUTOMATIC_PIPELINE &&
      this->Context.ComputeSupported);
  if (compute != this->UseCompute && this->Context.Window)
  {
    this->Composition.Reset();
    // The other pipeline's per-pixel memory is no longer needed.
    if (compute)
    {
      this->Fragment.ReleaseTargets(this->Context.Window);
    }
    else
    {
      this->Compute.ReleaseGraphicsResources(this->Context.Window);
    }
  }
  this->UseCompute = compute;
  return true;
}

//------------------------------------------------------------------------------
bool vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::RenderFragment(vtkOpenGLRenderWindow* window)
{
  vtkOpenGLTiledRayCastVolumeMapper* self = this->Self;
  vtkTiledRayCastFragmentPipeline::Frame frame;
  this->DescribeFrame(window, frame);
  frame.Reporter = self;
  frame.TileSize = self->GetTileSize();
  frame.TetsPerPass = self->GetTetsPerPass();
  frame.OcclusionQueryInterval = self->GetOcclusionQueryInterval();
  frame.MaximumPassesPerLayer = self->GetMaximumNumberOfPassesPerLayer();
  this->Fragment.Render(frame, *this, this->Timers, self->Statistics);
  return true;
}

//------------------------------------------------------------------------------
bool vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::RenderCompute(vtkOpenGLRenderWindow* window)
{
  vtkTiledRayCastStatistics* stats = this->Self->Statistics;
  vtkTiledRayCastComputePipeline::Frame frame;
  this->DescribeFrame(window, frame);
  frame.Verify = this->Self->SynchronousStatistics;
  frame.PeelStage = this->PeelStage();
  frame.Peel = &this->VolumetricPeel;
  frame.PeelVolume = this->FrameVolume;
  frame.Accumulation = frame.PeelStage > 0 ? vtkTiledRayCastPeelAccumulation::GetActive() : nullptr;
  std::copy(this->Geometry.NearPlane, this->Geometry.NearPlane + 3, frame.ViewDirection);
  frame.BoundsCoverage = this->Geometry.BoundsCoverage;
  frame.ViewportOrigin[0] = static_cast<float>(this->Viewport[0]);
  frame.ViewportOrigin[1] = static_cast<float>(this->Viewport[1]);
  if (!this->Group.empty())
  {
    // Overlapping volumes in one traversal: every volume's entries, their sums for the list.
    frame.NumberOfBoundaryFaces = 0;
    frame.NumberOfTetrahedra = 0;
    vtkIdType tets = 0; // the most of one volume: a layer's walk crosses one volume's tets
    for (vtkTiledRayCastGroupMember* member : this->Group)
    {
      frame.Members.push_back(member->GetGroupMember());
      frame.NumberOfBoundaryFaces += frame.Members.back().NumberOfBoundaryFaces;
      frame.NumberOfTetrahedra += frame.Members.back().NumberOfTetrahedra;
      tets = std::max(tets, frame.Members.back().NumberOfTetrahedra);
    }
    frame.MaximumSteps = static_cast<int>(std::min<vtkIdType>(tets + 1024, VTK_INT_MAX));
    frame.OpaqueDepthUnit = this->OpaqueDepth.GetTexture()->GetTextureUnit();
    frame.EarlyTerminationOpacity = static_cast<float>(this->Self->GetEarlyRayTerminationOpacity());
  }

  std::string error;
  if (!this->Compute.Render(frame, *this, this->Timers, stats, error))
  {
    this->ReportError(error);
    return false;
  }
  vtkInternalsCheckErrorMacro("failed after the compute pipeline");
  return true;
}

//------------------------------------------------------------------------------
bool vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::UpdateMesh(
  vtkDataObject* dataObject, vtkVolumeProperty* property)
{
  std::string error;
  this->MemoryBudget.Update(this->Context.Window, this->Self->GetMaximumGPUMemory(),
    this->MeshTextures.GetBytes() + this->VisibleMesh.GetBytes() + this->PointMotion.GetBytes());
  if (this->MovePointsOnGPU(dataObject, property))
  {
    return true;
  }
  this->MovedPoints = nullptr; // the CPU's mesh is current again
  if (!this->Reported(this->Mesh.Update(dataObject, property, this->Context.MaxTextureSize,
                        this->Context.MaxTextureBufferSize, this->MemoryBudget, error),
        error))
  {
    return false;
  }
  if (this->Mesh.TakeNewLayout())
  {
    this->MeshTextures.Invalidate();
  }
  return true;
}

//------------------------------------------------------------------------------
// A deforming mesh whose points alone moved: they go straight to the GPU
// (vtkTiledRayCastPointMotion). False where the CPU must update the mesh (Mesh.Update).
bool vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::MovePointsOnGPU(
  vtkDataObject* dataObject, vtkVolumeProperty* property)
{
  vtkOpenGLTiledRayCastVolumeMapper* self = this->Self;
  // The point texels are written in place: the textures must hold the layout as it is.
  const int where = self->GetPointUpdate();
  if (where == vtkTiledRayCastVolumeMapper::CPU_POINT_UPDATE ||
    (where == vtkTiledRayCastVolumeMapper::AUTOMATIC_POINT_UPDATE &&
      this->Context.SoftwareRasterizer) ||
    !this->Context.ComputeSupported || this->WarnedPointMotion ||
    !this->MeshTextures.IsCurrent(this->Mesh.GetLayout()))
  {
    return false;
  }
  vtkPointSet* input = this->Mesh.GetMovedPointsOnly(dataObject, property,
    this->Context.MaxTextureSize, this->Context.MaxTextureBufferSize, this->MemoryBudget);
  if (!input)
  {
    return false;
  }
  vtkTiledRayCastStatistics* stats = self->Statistics;
  vtkPoints* points = input->GetPoints();
  if (this->MovedPoints == points && this->MovedPointsTime == points->GetMTime())
  {
    stats->SetMeshRebuild(0); // moved there already: only the camera changed
    stats->SetMeshBuildTime(0.0);
    return true;
  }
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  double shift[3];
  vtkTiledRayCastMeshBuild::ShiftOf(input, shift);
  double longestEdge = 0.0;
  vtkIdType uploaded = 0;
  const vtkTiledRayCastPointMotion::Result result = this->PointMotion.Move(this->Context.Window,
    points->GetData(), this->Mesh.GetMesh(), this->Mesh.GetLayout(), this->MeshTextures,
    this->Mesh.GetDegeneracyTolerance(), shift, longestEdge, uploaded);
  stats->SetUploadedBytes(stats->GetUploadedBytes() + uploaded);
  const std::string& reason = this->PointMotion.GetReason();
  if (result == vtkTiledRayCastPointMotion::Unavailable && !this->WarnedPointMotion &&
    reason.rfind("Internal error", 0) == 0)
  {
    // A shader this GPU cannot build is a defect to hear of; the CPU rebuilds the points from
    // now on.
    vtkWarningWithObjectMacro(self,
      << "Moving the points on the GPU failed (" << reason << "); the CPU rebuilds them instead.");
    this->WarnedPointMotion = true;
  }
  if (result != vtkTiledRayCastPointMotion::Moved)
  {
    return false;
  }
  this->MovedPoints = points;
  this->MovedPointsTime = points->GetMTime();
  timer->StopTimer();
  this->Mesh.MovedPoints(input, longestEdge, timer->GetElapsedTime());
  return true;
}

//------------------------------------------------------------------------------
bool vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::UploadMesh(vtkOpenGLRenderWindow* window)
{
  vtkIdType uploaded = 0;
  std::string error;
  this->MeshTextures.SetSoftwareRasterizer(this->Context.SoftwareRasterizer);
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  if (!this->Reported(this->MeshTextures.Update(
                        window, this->Mesh.GetLayout(), this->Mesh.GetMesh(), uploaded, error),
        error))
  {
    return false;
  }
  timer->StopTimer();
  vtkTiledRayCastStatistics* stats = this->Self->Statistics;
  stats->SetUploadedBytes(stats->GetUploadedBytes() + uploaded);
  stats->SetMeshUploadTime(uploaded > 0 ? timer->GetElapsedTime() : 0.0);
  return true;
}

//------------------------------------------------------------------------------
bool vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::UpdateTransferFunction(
  vtkVolumeProperty* property, vtkOpenGLRenderWindow* window)
{
  vtkTiledRayCastIntegration::Frame frame;
  frame.Mapper = this->Self;
  frame.Window = window;
  frame.Mesh = this->Mesh.GetMesh();
  std::copy(this->Mesh.ScalarRange, this->Mesh.ScalarRange + 2, frame.ScalarRange);
  frame.LongestEdge = this->Mesh.LongestEdge;
  frame.TypicalEdge = this->Mesh.TypicalEdge;
  frame.ObjectToWorldNorm = this->Geometry.ObjectToWorldNorm;
  frame.MaxTextureSize = this->Context.MaxTextureSize;
  frame.Max3DTextureSize = this->Context.Max3DTextureSize;
  frame.WaitForChoice = this->Self->SynchronousStatistics;
  frame.MovedPoints = this->MovedPoints ? this->MovedPoints->GetData() : nullptr;
  std::string error;
  return this->Reported(this->Integration.Update(frame, property, error), error);
}

//------------------------------------------------------------------------------
bool vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::UpdateVisibleMesh(
  vtkOpenGLRenderWindow* window)
{
  vtkOpenGLTiledRayCastVolumeMapper* self = this->Self;
  // Zero opacity draws nothing only under composite blending: the other blend modes see the
  // scalars of every tet.
  const bool skip =
    self->GetEmptySpaceSkipping() && self->GetBlendMode() == vtkVolumeMapper::COMPOSITE_BLEND;
  vtkIdType uploaded = 0;
  std::string error;
  if (!this->VisibleMesh.Update(window, this->Mesh.GetMesh(),
        skip ? this->Integration.GetTransferFunction() : nullptr, this->Mesh.TextureBufferLimit,
        uploaded, error))
  {
    this->ReportError(error + ". Nothing is drawn.");
    return false;
  }
  vtkTiledRayCastStatistics* stats = self->Statistics;
  stats->SetUploadedBytes(stats->GetUploadedBytes() + uploaded);
  stats->SetTransferFunctionBuildTime(
    stats->GetTransferFunctionBuildTime() + this->VisibleMesh.GetBuildTime());
  stats->SetNumberOfVisibleTetrahedra(this->VisibleMesh.GetNumberOfVisibleTetrahedra());
  stats->SetNumberOfEntryFaces(this->VisibleMesh.GetNumberOfFaces());
  return true;
}

//------------------------------------------------------------------------------
vtkTiledRayCastShaderComposition::Inputs
vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::ProgramInputs(vtkOpenGLRenderWindow* window)
{
  vtkTiledRayCastShaderComposition::Inputs inputs;
  inputs.Window = window;
  inputs.Compute = this->UseCompute;
  inputs.PaperLayout = this->Mesh.LayoutKind == vtkTiledRayCastVolumeMapper::PAPER_LAYOUT;
  inputs.CellScalars = this->Mesh.HasCellScalars;
  vtkTetMeshLayout* layout = this->Mesh.GetLayout();
  if (!inputs.PaperLayout && layout && layout->GetValid())
  {
    inputs.TextureBufferShift = layout->GetTextureBufferShift();
    inputs.TetTextureBuffers =
      layout->GetNumberOfTextureBuffers(vtkTetMeshCompactLayout::TetPointsArray);
    inputs.PointTextureBuffers =
      layout->GetNumberOfTextureBuffers(vtkTetMeshCompactLayout::PointsArray);
  }
  inputs.IntegrationMode = this->IntegrationMode();
  inputs.BlendMode = this->Self->GetBlendMode();
  inputs.Shading = this->Lighting.Enabled;
  inputs.GradientOpacity = this->GradientOpacity.Enabled;
  inputs.SkipEmptySpace = this->VisibleMesh.GetSkipsEmptySpace();
  return inputs;
}

//------------------------------------------------------------------------------
bool vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::UpdatePrograms(vtkOpenGLRenderWindow* window)
{
  const vtkTiledRayCastShaderComposition::Inputs inputs = this->ProgramInputs(window);
  if (!this->Composition.Changed(inputs))
  {
    return true; // the programs of these inputs are built
  }
  const vtkTiledRayCastShaderComposition::Replacements common =
    vtkTiledRayCastShaderComposition::Compose(inputs, this->VisibleMesh.GetShaderDefinitions());
  vtkTiledRayCastStatistics* stats = this->Self->Statistics;
  stats->SetNumberOfShaderCompositions(stats->GetNumberOfShaderCompositions() + 1);
  std::string error;
  const bool built = this->UseCompute
    ? this->Compute.UpdatePrograms(window, common, error)
    : this->Fragment.UpdatePrograms(window, this->Context.VersionHeader, common, error);
  if (!this->Reported(built, error))
  {
    return false;
  }
  this->Composition.Built(inputs);
  return true;
}

//------------------------------------------------------------------------------
bool vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::UpdateTargets(
  vtkOpenGLRenderWindow* window, int width, int height)
{
  this->ImageSize[0] = width;
  this->ImageSize[1] = height;
  std::string error;
  return this->Reported(this->UseCompute
      ? this->Compute.UpdateTargets(window, width, height, error)
      : this->Fragment.UpdateTargets(window, width, height, error),
    error);
}

//------------------------------------------------------------------------------
bool vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::CaptureOpaqueDepth(
  vtkOpenGLRenderWindow* window, int width, int height)
{
  std::string error;
  this->Self->Statistics->SetSceneDepthCopied(this->SceneDepth);
  return this->Reported(this->SceneDepth
      ? this->OpaqueDepth.Capture(window, this->Viewport, width, height, this->ImageSize, error)
      : this->OpaqueDepth.SetFar(window, this->ImageSize, error),
    error);
}

//------------------------------------------------------------------------------
void vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::ReadTimers(bool wait)
{
  if (this->Timers.Read(wait, this->Self->Statistics))
  {
    // What AutoAdjustSampleDistances fits the next frames to.
    this->SampleDistance.Measured(
      this->TimedSampleDistance, 1e-3 * this->Self->Statistics->GetTotalGPUTime());
  }
}

//------------------------------------------------------------------------------
void vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::ActivateTextures(bool activate)
{
  // The mesh's textures take the first units, then the others in this order.
  this->MeshTextures.ActivateTextures(activate);
  Activate(this->OpaqueDepth.GetTexture(), activate);
  if (this->UseCompute)
  {
    Activate(this->Compute.GetColorTexture(), activate);
  }
  else
  {
    // The fragment pipeline's targets take the units after these.
    this->Fragment.ActivateTextures(activate);
  }
  this->Integration.ActivateTextures(this->IntegrationMode(), activate);
  // In a group's frame every volume's boundary faces are active only while its entries are
  // listed (ActivateEntryTextures): the units go to the volumes the traversal reads.
  this->VisibleMesh.ActivateTextures(activate, this->Group.empty(), true);
  for (size_t i = 1; i < this->Group.size(); ++i)
  {
    this->Group[i]->ActivateGroupTextures(activate);
  }
}

//------------------------------------------------------------------------------
void vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Compute.ReleaseGraphicsResources(window);
  this->MeshTextures.ReleaseGraphicsResources(this->Context.Window);
  this->PointMotion.ReleaseGraphicsResources();
  this->MovedPoints = nullptr;
  this->VisibleMesh.ReleaseGraphicsResources(window);
  this->Integration.ReleaseGraphicsResources(window);
  this->Fragment.ReleaseGraphicsResources(window);
  this->OpaqueDepth.ReleaseGraphicsResources(window);
  this->PeelAccumulation.ReleaseGraphicsResources(window);
  this->UseCompute = false;
  this->Composition.Reset();
  this->Timers.ReleaseGraphicsResources();
  this->ImageSize[0] = this->ImageSize[1] = 0;
  this->Context.Reset();
}

//------------------------------------------------------------------------------
vtkOpenGLTiledRayCastVolumeMapper::vtkOpenGLTiledRayCastVolumeMapper()
  : Impl(new vtkInternals(this))
  , ResourceCallback(new vtkTiledRayCastResourceFreeCallback<vtkOpenGLTiledRayCastVolumeMapper>(
      this, &vtkOpenGLTiledRayCastVolumeMapper::ReleaseGraphicsResources))
{
}

//------------------------------------------------------------------------------
vtkOpenGLTiledRayCastVolumeMapper::~vtkOpenGLTiledRayCastVolumeMapper()
{
  this->Impl->Deferred.Stop();
  // Frees the GL objects in their own context, if the window still exists.
  this->ResourceCallback->Release();
  delete this->ResourceCallback;
  delete this->Impl;
}

//------------------------------------------------------------------------------
void vtkOpenGLTiledRayCastVolumeMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  // Called by users and by the window (through the callback, with the context current).
  if (!this->ResourceCallback->IsReleasing())
  {
    this->ResourceCallback->Release();
    return;
  }
  this->Impl->ReleaseGraphicsResources(window);
  this->Statistics->SetMeshBytes(0);
  this->Statistics->SetTransferFunctionBytes(0);
  this->Statistics->SetRenderTargetBytes(0);
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkOpenGLTiledRayCastVolumeMapper::IsSupported(vtkRenderWindow* window)
{
  vtkOpenGLRenderWindow* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  return gl && vtkTiledRayCastContext::FragmentPipelineVersion(gl) != nullptr;
}

//------------------------------------------------------------------------------
int vtkOpenGLTiledRayCastVolumeMapper::IsRenderSupported(
  vtkRenderWindow* window, vtkVolumeProperty* vtkNotUsed(property))
{
  vtkOpenGLRenderWindow* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!gl || this->BlendMode != vtkUnstructuredGridVolumeMapper::COMPOSITE_BLEND)
  {
    return 0;
  }
  if (this->Pipeline == vtkTiledRayCastVolumeMapper::COMPUTE_PIPELINE)
  {
    return vtkTiledRayCastComputeShader::IsSupported(gl) ? 1 : 0;
  }
  return vtkOpenGLTiledRayCastVolumeMapper::IsSupported(window) ? 1 : 0;
}

//------------------------------------------------------------------------------
bool vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::PrepareFrame(vtkRenderer* ren, vtkVolume* vol,
  vtkDataObject* input, vtkVolumeProperty* property, vtkOpenGLRenderWindow* window, int rays[2],
  bool targets)
{
  // CPU work: only what changed.
  vtkOpenGLTiledRayCastVolumeMapper* self = this->Self;
  this->FrameVolume = vol;
  const int width = this->Viewport[2];
  const int height = this->Viewport[3];
  if (!this->UpdateMesh(input, property))
  {
    return false;
  }
  if (!this->Geometry.Compute(ren, vol, this->Mesh.Shift, this->Mesh.MeshBounds))
  {
    this->ReportError("The camera and volume matrices give no usable rays. Nothing is drawn.");
    return false;
  }
  // Inside VTK's depth peeling the pass's depth ranges end the rays (its framebuffer has no
  // depth to copy).
  this->SceneDepth = this->PeelStage() == 0 && vtkTiledRayCastOpaqueDepth::SceneMayHaveDepth(ren);
  this->Lighting.Compute(ren, vol, self->BlendMode);
  this->GradientOpacity.Compute(property, self->BlendMode);
  this->WarnLighting();
  if (!this->Geometry.ComputeClippingPlanes(self->ClippingPlanes, this->Mesh.MeshBounds) &&
    !this->WarnedClippingPlanes)
  {
    vtkErrorWithObjectMacro(
      self, << self->GetNumberOfClippingPlanes() << " clipping planes are set; this mapper "
            << "clips with the first " << vtkTiledRayCastFrameGeometry::MaximumClippingPlanes
            << " (as VTK's OpenGL mappers).");
    this->WarnedClippingPlanes = true;
  }
  if (this->Geometry.ClippedAway)
  {
    return false; // the clipping planes leave nothing of the mesh: nothing is visible
  }
  // Interaction: fewer rays while a full frame would not fit the time the renderer allocated
  // the volume (vtkTiledRayCastSampleDistance).
  // Inside VTK's depth peeling, one ray per pixel of the pass's textures.
  this->FrameSampleDistance = this->PeelStage() > 0
    ? 1.0
    : this->SampleDistance.Choose(self->AutoAdjustSampleDistances != 0, self->ImageSampleDistance,
        self->MinimumImageSampleDistance, self->MaximumImageSampleDistance,
        vol->GetAllocatedRenderTime());
  vtkTiledRayCastSampleDistance::ComputeImageSize(width, height, this->FrameSampleDistance, rays);
  if (!this->UploadMesh(window) || !this->UpdateTransferFunction(property, window) ||
    !this->UpdateVisibleMesh(window) || !this->UpdatePrograms(window) ||
    (targets && !this->UpdateTargets(window, rays[0], rays[1])))
  {
    return false;
  }
  std::string error;
  if (targets && this->PeelStage() > 0 &&
    !this->Reported(this->Compute.PreparePeel(window, this->PeelStage(), error), error))
  {
    return false;
  }
  this->Warnings.ClearError();
  this->ReadTimers(self->SynchronousStatistics);
  return true;
}

//------------------------------------------------------------------------------
bool vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::DrawFrame(
  vtkOpenGLRenderWindow* window, const int rays[2])
{
  // GPU work.
  vtkOpenGLTiledRayCastVolumeMapper* self = this->Self;
  const int width = this->Viewport[2];
  const int height = this->Viewport[3];
  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglEnableDisable depthTestSaver(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable cullSaver(state, GL_CULL_FACE);
  vtkOpenGLState::ScopedglEnableDisable scissorSaver(state, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(state);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(state);
  vtkOpenGLState::ScopedglColorMask colorMaskSaver(state);
  vtkOpenGLState::ScopedglClearColor clearColorSaver(state);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(state);
  vtkOpenGLState::ScopedglViewport viewportSaver(state);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglDisable(GL_BLEND);

  // GPU timers of the previous frame still in flight are not restarted: this frame is then not
  // timed, and the statistics keep the latest times measured.
  if (this->Timers.BeginFrame())
  {
    this->TimedSampleDistance = this->FrameSampleDistance;
  }
  this->Timers.Start(vtkTiledRayCastPhaseTimers::Total);
  // The opaque geometry drawn so far ends the rays.
  if (!this->CaptureOpaqueDepth(window, width, height))
  {
    return false;
  }

  state->PushFramebufferBindings();
  state->vtkglViewport(0, 0, rays[0], rays[1]);
  int cullFaceMode = GL_BACK;
  state->vtkglGetIntegerv(GL_CULL_FACE_MODE, &cullFaceMode);
  this->ActivateTextures(true);
  vtkTiledRayCastStatistics* stats = self->Statistics;
  stats->SetPipeline(this->UseCompute ? "Compute" : "Fragment");
  const bool ok = this->UseCompute ? this->RenderCompute(window) : this->RenderFragment(window);
  this->Timers.Stop(vtkTiledRayCastPhaseTimers::Total);
  this->Timers.EndFrame();
  state->vtkglCullFace(cullFaceMode);
  this->ActivateTextures(false);
  if (!ok)
  {
    return false;
  }
  if (self->SynchronousStatistics)
  {
    if (this->UseCompute)
    {
      this->Compute.ReadCounts(stats);
    }
    this->ReadTimers(true);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::WarnAfterFrame()
{
  // Only the compute pipeline stops rays or misses layers.
  if (this->UseCompute)
  {
    this->Warnings.WarnAfterFrame(this->Compute.GetNumberOfRaysStopped(),
      this->Compute.TakeNumberOfRaysIncomplete(), this->Self->Statistics->GetNumberOfEntries());
  }
}

//------------------------------------------------------------------------------
void vtkOpenGLTiledRayCastVolumeMapper::Render(vtkRenderer* ren, vtkVolume* vol)
{
  if (vtkTiledRayCastVolumeGroup::WasDrawn(ren, vol))
  {
    return; // drawn with the volumes it overlaps, or in depth order, by another's mapper
  }
  // VTK draws volumes in the order they were added: the first of ours (the visible volumes of
  // this module's mappers in the renderer, grouped below where they overlap) draws all of them,
  // farthest first; inside VTK's depth peeling, in each of its stages, between the stage's
  // depths.
  const std::vector<vtkTiledRayCastVolumeGroup::Candidate> ours =
    this->Impl->FindOurVolumes(ren, vol);
  // (A volume drawn after VTK's depth peeling, which it could not take part in, draws itself.)
  if (!this->Impl->Deferred.IsDrawing() &&
    vtkTiledRayCastVolumeGroup::RenderInDepthOrder(ren, ours, vol))
  {
    return;
  }
  this->Timer->StartTimer();
  this->Statistics->ResetFrameCounts();
  vtkInternals* impl = this->Impl;

  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!window)
  {
    impl->ReportError("The tiled ray-cast mapper needs an OpenGL render window.");
    return;
  }
  vtkTiledRayCastDebugEvent event("Render");
  this->ResourceCallback->RegisterGraphicsResources(window);
  if (!impl->CheckContext(window))
  {
    impl->ReportError(impl->Context.Error);
    return;
  }
  if (!impl->ChoosePipeline())
  {
    return;
  }
  // VTK's dual depth peeling for volumes draws the volume once per stage of its peeling and
  // asks for the volume between depths of its own (vtkTiledRayCastVolumetricPeel): the compute
  // pipeline takes part. Where the volume cannot, it draws nothing in the peels and draws the
  // volume once the renderer has finished, over the composited scene, as without depth peeling
  // for volumes (the translucent-geometry warning below says so, once).
  if (impl->VolumetricPeel.Update(this, vol) != vtkTiledRayCastVolumetricPeel::NotPeeling &&
    !impl->TakesPartInPeeling() && impl->Deferred.Defer(ren, vol))
  {
    return;
  }
  if (!impl->TakesPartInPeeling())
  {
    impl->WarnTranslucentGeometry(ren, vol);
  }
  if (!impl->CheckBlendMode())
  {
    return;
  }
  vtkVolumeProperty* property = vol->GetProperty();
  // A vtkUnstructuredGridBase or a composite data set (vtkDataObjectTree).
  vtkDataObject* input =
    this->GetNumberOfInputConnections(0) > 0 ? this->GetInputDataObject(0, 0) : nullptr;
  if (!input)
  {
    impl->ReportError("No input. Nothing is drawn.");
    return;
  }
  if (!property)
  {
    impl->ReportError("The volume has no property. Nothing is drawn.");
    return;
  }

  int width = 0, height = 0;
  ren->GetTiledSizeAndOrigin(&width, &height, &impl->Viewport[0], &impl->Viewport[1]);
  impl->Viewport[2] = width;
  impl->Viewport[3] = height;
  if (width <= 0 || height <= 0)
  {
    return;
  }
  if (impl->PeelStage() > 0)
  {
    // The peeling pass draws into textures of the viewport's size, from their origin.
    impl->Viewport[0] = impl->Viewport[1] = 0;
  }

  // Overlapping volumes of our mappers: the first drawn draws them all in one traversal (inside
  // VTK's depth peeling, in each of its stages).
  impl->GroupSize = ours.size() < 2 ? 1
                                    : vtkTiledRayCastVolumeGroup::Render(
                                        ren, window, vtkTiledRayCastVolumeGroup::Select(ours, vol));
  if (impl->GroupSize > 1)
  {
    impl->WarnAfterFrame();
    this->FinishRender(impl->Compute.GetTargetBytes() + impl->PeelAccumulation.GetBytes() +
      4 * static_cast<vtkIdType>(width) * height);
    return;
  }
  impl->GroupSize = 1;
  impl->Integration.SetForcePartial(false);
  int rays[2];
  if (!impl->PrepareFrame(ren, vol, input, property, window, rays) ||
    !impl->DrawFrame(window, rays))
  {
    return;
  }
  impl->WarnAfterFrame();
  // Per pixel: the compute pipeline's targets, the scene depth (4 B) and any accumulation of
  // several volumes in VTK's depth peeling; or the fragment pipeline's.
  const vtkIdType pixels = static_cast<vtkIdType>(width) * height;
  this->FinishRender(impl->UseCompute
      ? impl->Compute.GetTargetBytes() + impl->PeelAccumulation.GetBytes() + 4 * pixels
      : vtkTiledRayCastFragmentPipeline::GetBytesPerPixel() * pixels);
}

//------------------------------------------------------------------------------
void vtkOpenGLTiledRayCastVolumeMapper::FinishRender(vtkIdType renderTargetBytes)
{
  vtkInternals* impl = this->Impl;
  vtkTiledRayCastStatistics* stats = this->Statistics;
  stats->SetRendered(true);
  // The peeling draws the volume 1 + peels (+ 1) times a frame, from stage 1 (BeforePeels).
  const int stage = impl->PeelStage();
  stats->SetDepthPeelingStage(stage);
  stats->SetNumberOfDepthPeelingDraws(stage == 0 ? 0
      : stage == 1                               ? 1
                                                 : stats->GetNumberOfDepthPeelingDraws() + 1);
  stats->SetImageSize(impl->ImageSize);
  stats->SetNumberOfGroupedVolumes(impl->GroupSize);
  stats->SetGroupCodeShared(impl->GroupSize > 1 && impl->Compute.GetGroupCodeShared());
  stats->SetImageSampleDistance(impl->FrameSampleDistance);
  // The layout's textures, the faces rays enter by and the visible bits.
  const vtkIdType meshBytes =
    impl->MeshTextures.GetBytes() + impl->VisibleMesh.GetBytes() + impl->PointMotion.GetBytes();
  stats->SetMeshBytes(meshBytes);
  stats->SetMeshBytesPerTetrahedron(
    impl->Mesh.NumberOfTets > 0 ? static_cast<double>(meshBytes) / impl->Mesh.NumberOfTets : 0.0);
  stats->SetNumberOfMeshTextures(impl->MeshTextures.GetNumberOfTextures());
  stats->SetTransferFunctionBytes(impl->Integration.GetBytes());
  stats->SetRenderTargetBytes(renderTargetBytes);
  vtkOpenGLCheckErrorMacro("failed after Render");

  this->Timer->StopTimer();
  this->TimeToDraw = this->Timer->GetElapsedTime();
  stats->SetRenderTime(this->TimeToDraw);
}

//------------------------------------------------------------------------------
void vtkOpenGLTiledRayCastVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
