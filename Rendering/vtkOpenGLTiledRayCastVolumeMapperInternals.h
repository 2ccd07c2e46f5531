/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkOpenGLTiledRayCastVolumeMapperInternals.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkOpenGLTiledRayCastVolumeMapper::vtkInternals
 * @brief   the OpenGL objects and parts of vtkOpenGLTiledRayCastVolumeMapper
 *
 * Declared here, not in vtkOpenGLTiledRayCastVolumeMapper.cxx, so that the mapper's
 * implementation can span two files: vtkOpenGLTiledRayCastVolumeMapper.cxx (the frame of one
 * volume) and vtkOpenGLTiledRayCastVolumeMapperGroup.cxx (its part in a group of overlapping
 * volumes, vtkTiledRayCastGroupMember).
 *
 * Private to the module: not wrapped, not installed.
 */

#ifndef vtkOpenGLTiledRayCastVolumeMapperInternals_h
#define vtkOpenGLTiledRayCastVolumeMapperInternals_h

#include "vtkOpenGLTiledRayCastVolumeMapper.h"
#include "vtkTiledRayCastComputePipeline.h"      // For vtkTiledRayCastComputePipeline
#include "vtkTiledRayCastContext.h"              // For vtkTiledRayCastContext
#include "vtkTiledRayCastDeferredDraw.h"         // For vtkTiledRayCastDeferredDraw
#include "vtkTiledRayCastFragmentPipeline.h"     // For vtkTiledRayCastFragmentPipeline
#include "vtkTiledRayCastFrameGeometry.h"        // For vtkTiledRayCastFrameGeometry
#include "vtkTiledRayCastGradientOpacityNodes.h" // For vtkTiledRayCastGradientOpacityNodes
#include "vtkTiledRayCastIntegration.h"          // For vtkTiledRayCastIntegration
#include "vtkTiledRayCastLighting.h"             // For vtkTiledRayCastLighting
#include "vtkTiledRayCastMemoryBudget.h"         // For vtkTiledRayCastMemoryBudget
#include "vtkTiledRayCastMeshBuild.h"            // For vtkTiledRayCastMeshBuild
#include "vtkTiledRayCastMeshTextures.h"         // For vtkTiledRayCastMeshTextures
#include "vtkTiledRayCastOpaqueDepth.h"          // For vtkTiledRayCastOpaqueDepth
#include "vtkTiledRayCastPeelAccumulation.h"     // For vtkTiledRayCastPeelAccumulation
#include "vtkTiledRayCastPhaseTimers.h"          // For vtkTiledRayCastPhaseTimers
#include "vtkTiledRayCastPointMotion.h"          // For vtkTiledRayCastPointMotion
#include "vtkTiledRayCastSampleDistance.h"       // For vtkTiledRayCastSampleDistance
#include "vtkTiledRayCastShaderComposition.h"    // For vtkTiledRayCastShaderComposition
#include "vtkTiledRayCastUniforms.h"             // For vtkTiledRayCastUniforms
#include "vtkTiledRayCastVisibleMesh.h"          // For vtkTiledRayCastVisibleMesh
#include "vtkTiledRayCastVolumeGroup.h"          // For vtkTiledRayCastGroupMember
#include "vtkTiledRayCastVolumetricPeel.h"       // For vtkTiledRayCastVolumetricPeel
#include "vtkTiledRayCastWarnings.h"             // For vtkTiledRayCastWarnings

#include <algorithm> // For std::min, std::copy
#include <string>    // For std::string
#include <vector>    // For std::vector

class vtkDataObject;
class vtkOpenGLRenderWindow;
class vtkRenderer;
class vtkShaderProgram;
class vtkVolume;
class vtkVolumeProperty;
class vtkWindow;

//------------------------------------------------------------------------------
class vtkOpenGLTiledRayCastVolumeMapper::vtkInternals : public vtkTiledRayCastGroupMember
{
public:
  explicit vtkInternals(vtkOpenGLTiledRayCastVolumeMapper* self)
    : Self(self)
    , Deferred(self)
    , Mesh(self)
    , Warnings(self)
  {
  }

  vtkOpenGLTiledRayCastVolumeMapper* Self;

  // VTK's dual depth peeling for volumes: the stage drawing this volume now; where the volume
  // cannot take part (TakesPartInPeeling), its drawing is deferred to the renderer's EndEvent.
  vtkTiledRayCastVolumetricPeel VolumetricPeel;
  vtkTiledRayCastDeferredDraw Deferred;
  // Whether this frame's volume takes part in the peeling stage drawing it: the compute
  // pipeline, compositing, a stage it knows.
  bool TakesPartInPeeling() const
  {
    const int stage = this->VolumetricPeel.GetStage();
    return this->UseCompute &&
      this->Self->GetBlendMode() == vtkUnstructuredGridVolumeMapper::COMPOSITE_BLEND &&
      stage >= vtkTiledRayCastVolumetricPeel::BeforePeels &&
      stage <= vtkTiledRayCastVolumetricPeel::Remainder;
  }
  // The stage this frame draws for (0 when not taking part in depth peeling).
  int PeelStage() const { return this->TakesPartInPeeling() ? this->VolumetricPeel.GetStage() : 0; }

  // Context: checked once per window.
  vtkTiledRayCastContext Context;

  // The pipeline of this frame: compute or fragment.
  bool UseCompute = false;
  vtkTiledRayCastComputePipeline Compute;
  vtkTiledRayCastFragmentPipeline Fragment;
  // What the pipeline's programs were last built from.
  vtkTiledRayCastShaderComposition Composition;

  // CPU mesh and its layout.
  vtkTiledRayCastMeshBuild Mesh;
  vtkTiledRayCastMeshTextures MeshTextures;
  vtkTiledRayCastMemoryBudget MemoryBudget; // what the mesh may take on the GPU
  // A deforming mesh's points moved on the GPU, and the input points last moved there (not
  // held; with their time): the CPU mesh keeps older ones until a build on the CPU.
  vtkTiledRayCastPointMotion PointMotion;
  vtkPoints* MovedPoints = nullptr;
  vtkMTimeType MovedPointsTime = 0;
  bool WarnedPointMotion = false;
  // The faces rays enter by, and which tets they may cross (empty-space skipping).
  vtkTiledRayCastVisibleMesh VisibleMesh;

  // Transfer function.
  vtkTiledRayCastIntegration Integration;

  // The scene's depth, which ends the rays, and whether this frame's scene may have any.
  vtkTiledRayCastOpaqueDepth OpaqueDepth;
  bool SceneDepth = true;
  // The rays of this frame: the viewport's pixels, or fewer at an image sample distance above 1.
  int ImageSize[2] = { 0, 0 };
  vtkTiledRayCastSampleDistance SampleDistance;
  double FrameSampleDistance = 1.0;
  double TimedSampleDistance = 1.0; // of the frame the timers in flight measure

  // GPU timers.
  vtkTiledRayCastPhaseTimers Timers;

  // Warnings given once, errors once until they change.
  vtkTiledRayCastWarnings Warnings;
  bool WarnedClippingPlanes = false;
  bool WarnedGroup = false;

  // Overlapping volumes (vtkTiledRayCastVolumeGroup): the volumes this mapper draws in this
  // frame's traversal (empty when it draws its own alone), and how many were drawn together.
  std::vector<vtkTiledRayCastGroupMember*> Group;
  int GroupSize = 1;
  // vtkTiledRayCastGroupMember, and FindOurVolumes: vtkOpenGLTiledRayCastVolumeMapperGroup.cxx.
  std::string GetGroupRefusal(vtkVolume* volume, bool prepared) override;
  bool PrepareGroupFrame(vtkRenderer* ren, vtkVolume* vol, vtkOpenGLRenderWindow* window,
    bool draws, int rays[2]) override;
  vtkTiledRayCastShaderComposition::Inputs GetGroupInputs() override;
  vtkTiledRayCastComputePipeline::Replacements GetGroupCode() override;
  vtkTiledRayCastComputePipeline::Member GetGroupMember() override;
  int GetGroupTextureUnits() override;
  void ActivateEntryTextures(bool activate) override
  {
    this->VisibleMesh.ActivateTextures(activate, true, false);
  }
  void ActivateGroupTextures(bool activate) override;
  bool DrawGroup(vtkOpenGLRenderWindow* window, const int rays[2],
    const std::vector<vtkTiledRayCastGroupMember*>& members) override;
  void FinishGroupFrame(int volumes) override;
  void WarnGroupOnce(const std::string& text) override;
  bool BeginDepthOrder(vtkRenderer* ren, vtkVolume* vol, bool stage) override;
  void FinishDepthOrder(vtkRenderer* ren, vtkVolume* vol, bool stage, int sets) override;
  // Several sets of our volumes in a stage of VTK's depth peeling, drawn by this mapper.
  vtkTiledRayCastPeelAccumulation PeelAccumulation;
  // The visible volumes of this module's OpenGL mappers in `ren` (and `vol`), in its order.
  std::vector<vtkTiledRayCastVolumeGroup::Candidate> FindOurVolumes(
    vtkRenderer* ren, vtkVolume* vol);
  vtkTiledRayCastShaderComposition::Inputs ProgramInputs(vtkOpenGLRenderWindow* window);

  // This frame.
  vtkTiledRayCastFrameGeometry Geometry;
  vtkVolume* FrameVolume = nullptr; // the volume of the frame being drawn (not held)
  vtkTiledRayCastLighting Lighting;
  vtkTiledRayCastGradientOpacityNodes GradientOpacity;
  int Viewport[4] = { 0, 0, 0, 0 };

  // The uniforms, read from the members above when the pipelines set up their programs.
  vtkTiledRayCastUniforms Uniforms{ { this->Self, &this->Geometry, this->ImageSize, this->Viewport,
    &this->OpaqueDepth, &this->Mesh, &this->MeshTextures, &this->VisibleMesh, &this->Integration,
    &this->Lighting, &this->GradientOpacity } };

  void ReportError(const std::string& message) { this->Warnings.ReportError(message); }
  // `ok`, after reporting `error` where it is false (the parts return false with a message).
  bool Reported(bool ok, const std::string& error)
  {
    if (!ok)
    {
      this->ReportError(error);
    }
    return ok;
  }
  // The integration the shaders do (vtkTiledRayCastIntegration::GetMode).
  int IntegrationMode() const { return this->Integration.GetMode(this->Self); }
  // Once each: what shading and gradient opacity do not do as asked (this frame's Lighting and
  // GradientOpacity).
  void WarnLighting()
  {
    this->Warnings.WarnLighting(this->Lighting, this->GradientOpacity, this->Mesh.HasCellScalars);
  }
  bool CheckContext(vtkOpenGLRenderWindow* window) { return this->Context.Check(window); }
  bool UpdateMesh(vtkDataObject* input, vtkVolumeProperty* property);
  bool MovePointsOnGPU(vtkDataObject* input, vtkVolumeProperty* property);
  bool UploadMesh(vtkOpenGLRenderWindow* window);
  bool UpdateTransferFunction(vtkVolumeProperty* property, vtkOpenGLRenderWindow* window);
  bool UpdateVisibleMesh(vtkOpenGLRenderWindow* window);
  bool UpdatePrograms(vtkOpenGLRenderWindow* window);
  bool UpdateTargets(vtkOpenGLRenderWindow* window, int width, int height);
  bool CaptureOpaqueDepth(vtkOpenGLRenderWindow* window, int width, int height);
  void ReadTimers(bool wait);

  void ActivateTextures(bool activate);
  bool ChoosePipeline();
  // vtkTiledRayCastProgramSetup, for the pipelines: vtkTiledRayCastUniforms sets them.
  void SetFrameUniforms(vtkShaderProgram* p) override { this->Uniforms.SetFrameUniforms(p); }
  void SetMeshUniforms(vtkShaderProgram* p) override { this->Uniforms.SetMeshUniforms(p); }
  void SetCoverageUniforms(vtkShaderProgram* p) override { this->Uniforms.SetCoverageUniforms(p); }
  void SetIntegrationUniforms(vtkShaderProgram* p) override
  {
    this->Uniforms.SetIntegrationUniforms(p);
  }
  void SetSampleScaleUniforms(vtkShaderProgram* p) override
  {
    this->Uniforms.SetSampleScaleUniforms(p);
  }
  int GetMaximumSteps() const
  {
    // More than any ray can need in one layer: every tet once, plus the stalled steps allowed.
    return static_cast<int>(std::min<vtkIdType>(this->Mesh.NumberOfTets + 1024, VTK_INT_MAX));
  }
  // Two boundary faces whose entry points on a ray are closer than this (in lambda) are one
  // place: the next layer must then have a larger key than the last (both pipelines' peeling).
  static constexpr float PeelEpsilon = 2e-6f;
  // What both pipelines' frames say alike: the window, the rays, the viewport they composite
  // into, the entry faces and tets, the view's near plane and handedness, the step bound and the
  // peeling tolerance.
  template <typename FrameType>
  void DescribeFrame(vtkOpenGLRenderWindow* window, FrameType& frame) const
  {
    frame.Window = window;
    frame.Width = this->ImageSize[0];
    frame.Height = this->ImageSize[1];
    std::copy(this->Viewport, this->Viewport + 4, frame.Viewport);
    frame.NumberOfBoundaryFaces = this->VisibleMesh.GetNumberOfFaces();
    frame.NumberOfTetrahedra = this->Mesh.NumberOfTets;
    frame.NearPlaneCutsMesh = this->Geometry.NearPlaneCutsMesh;
    frame.Mirrored = this->Geometry.Mirrored;
    frame.MaximumSteps = this->GetMaximumSteps();
    frame.PeelEpsilon = PeelEpsilon;
  }
  // The GPU work of a frame in each pipeline, from the first hit to compositing (the caller
  // has pushed the framebuffer bindings; both pop them before compositing).
  bool RenderCompute(vtkOpenGLRenderWindow* window);
  bool RenderFragment(vtkOpenGLRenderWindow* window);

  // The steps of Render.
  void WarnTranslucentGeometry(vtkRenderer* ren, vtkVolume* vol)
  {
    this->Warnings.WarnTranslucentGeometry(ren, vol);
  }
  bool CheckBlendMode()
  {
    return this->Warnings.CheckBlendMode(this->Self->BlendMode, this->UseCompute);
  }
  // The CPU work of a frame (only what changed) and the GPU resources it needs; false when
  // nothing is drawn. Sets the number of rays along x and y. Without `targets` (a volume drawn
  // by another's mapper) no per-pixel targets.
  bool PrepareFrame(vtkRenderer* ren, vtkVolume* vol, vtkDataObject* input,
    vtkVolumeProperty* property, vtkOpenGLRenderWindow* window, int rays[2], bool targets = true);
  // The GPU work of a frame, in the OpenGL state it restores.
  bool DrawFrame(vtkOpenGLRenderWindow* window, const int rays[2]);
  void WarnAfterFrame();

  void ReleaseGraphicsResources(vtkWindow* window);
};

#endif
// VTK-HeaderTest-Exclude: vtkOpenGLTiledRayCastVolumeMapperInternals.h
