/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkOpenGLTiledRayCastVolumeMapperGroup.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkOpenGLTiledRayCastVolumeMapper's internals as a vtkTiledRayCastGroupMember: what
// vtkTiledRayCastVolumeGroup needs of the mapper to draw overlapping volumes in one traversal.
// Apart from vtkOpenGLTiledRayCastVolumeMapper.cxx only to keep that file short.
#include "vtkOpenGLTiledRayCastVolumeMapperInternals.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTextureUnitManager.h"
#include "vtkTiledRayCastResourceFreeCallback.h"
#include "vtkTiledRayCastStatistics.h"
#include "vtkTimerLog.h"
#include "vtkVolume.h"
#include "vtkVolumeCollection.h"

#include <algorithm>
#include <string>
#include <vector>

//------------------------------------------------------------------------------
// Overlapping volumes (vtkTiledRayCastVolumeGroup): what a group needs of this mapper.
std::vector<vtkTiledRayCastVolumeGroup::Candidate>
vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::FindOurVolumes(vtkRenderer* ren, vtkVolume* vol)
{
  // The visible volumes of our mappers in this renderer, in its order (the others' internals
  // are reachable here: they are this class's).
  std::vector<vtkTiledRayCastVolumeGroup::Candidate> candidates;
  vtkVolumeCollection* volumes = ren->GetVolumes();
  vtkCollectionSimpleIterator it;
  volumes->InitTraversal(it);
  while (vtkVolume* volume = volumes->GetNextVolume(it))
  {
    auto* mapper = vtkOpenGLTiledRayCastVolumeMapper::SafeDownCast(volume->GetMapper());
    if (mapper && (volume == vol || volume->GetVisibility()))
    {
      candidates.push_back({ volume, mapper->Impl });
    }
  }
  return candidates;
}

//------------------------------------------------------------------------------
std::string vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::GetGroupRefusal(
  vtkVolume* volume, bool prepared)
{
  // What this frame found (after PrepareFrame): shading or gradient opacity in force.
  const bool lit = prepared && (this->Lighting.Enabled || this->GradientOpacity.Enabled);
  return vtkTiledRayCastVolumeGroup::Refusal(
    this->Self, volume, this->Context.Window && !this->Context.ComputeSupported, lit);
}

//------------------------------------------------------------------------------
bool vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::PrepareGroupFrame(
  vtkRenderer* ren, vtkVolume* vol, vtkOpenGLRenderWindow* window, bool draws, int rays[2])
{
  vtkOpenGLTiledRayCastVolumeMapper* self = this->Self;
  if (!draws)
  {
    // Drawn by another mapper: this frame's statistics start here, not in Render().
    self->Timer->StartTimer();
    self->Statistics->ResetFrameCounts();
    self->ResourceCallback->RegisterGraphicsResources(window);
    if (!this->CheckContext(window) || !this->ChoosePipeline())
    {
      return false;
    }
    // Inside VTK's depth peeling the group is drawn in the stage drawing the first volume.
    this->VolumetricPeel.Update(self, vol);
  }
  int width = 0, height = 0;
  ren->GetTiledSizeAndOrigin(&width, &height, &this->Viewport[0], &this->Viewport[1]);
  this->Viewport[2] = width;
  this->Viewport[3] = height;
  if (this->PeelStage() > 0)
  {
    // The peeling pass draws into textures of the viewport's size, from their origin.
    this->Viewport[0] = this->Viewport[1] = 0;
  }
  int own[2];
  // The group's mixture reads every volume's transfer-function nodes.
  this->Integration.SetForcePartial(true);
  if (!this->UseCompute ||
    !this->PrepareFrame(ren, vol, self->GetInputDataObject(0, 0), vol->GetProperty(), window,
      draws ? rays : own, draws))
  {
    return false;
  }
  // One image for the group: the first volume's rays.
  std::copy(rays, rays + 2, this->ImageSize);
  return true;
}

//------------------------------------------------------------------------------
vtkTiledRayCastShaderComposition::Inputs
vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::GetGroupInputs()
{
  return this->ProgramInputs(this->Context.Window);
}

//------------------------------------------------------------------------------
vtkTiledRayCastComputePipeline::Replacements
vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::GetGroupCode()
{
  return vtkTiledRayCastShaderComposition::Compose(
    this->ProgramInputs(this->Context.Window), this->VisibleMesh.GetShaderDefinitions());
}

//------------------------------------------------------------------------------
vtkTiledRayCastComputePipeline::Member
vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::GetGroupMember()
{
  vtkTiledRayCastComputePipeline::Member member;
  member.Setup = this;
  member.NumberOfBoundaryFaces = this->VisibleMesh.GetNumberOfFaces();
  member.NumberOfTetrahedra = this->Mesh.NumberOfTets;
  member.NearPlaneCutsMesh = this->Geometry.NearPlaneCutsMesh;
  member.Mirrored = this->Geometry.Mirrored;
  return member;
}

//------------------------------------------------------------------------------
void vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::ActivateGroupTextures(bool activate)
{
  // What the traversal reads of this volume: its mesh, transfer function and visible bits (the
  // Psi table is the first volume's; the boundary faces only while its entries are listed).
  this->MeshTextures.ActivateTextures(activate);
  this->Integration.ActivateTextures(this->IntegrationMode(), activate, false);
  this->VisibleMesh.ActivateTextures(activate, false, true);
}

//------------------------------------------------------------------------------
int vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::GetGroupTextureUnits()
{
  vtkOpenGLRenderWindow* window = this->Context.Window;
  if (!window || !this->Context.ComputeSupported)
  {
    return 0;
  }
  // The units VTK has not handed out (the scene's own textures, VTK's depth peeling's, hold
  // theirs), of which the group itself holds the scene's depth, the colour, the Psi table and
  // one volume's boundary faces at a time; and the samplers a compute shader may read, of which
  // the volumes share the scene's depth, the Psi table and the stage's depths.
  vtkTextureUnitManager* units = window->GetTextureUnitManager();
  int free = 0;
  for (int i = 0; i < units->GetNumberOfTextureUnits(); ++i)
  {
    free += units->IsAllocated(i) ? 0 : 1;
  }
  const int stage = this->PeelStage();
  return std::min(free - 4,
    this->Context.MaxComputeTextureUnits -
      vtkTiledRayCastGroupTraversal::GetSharedTextureUnits(stage));
}

//------------------------------------------------------------------------------
bool vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::DrawGroup(vtkOpenGLRenderWindow* window,
  const int rays[2], const std::vector<vtkTiledRayCastGroupMember*>& members)
{
  // The programs are composed (every volume's GLSL, then compared with the programs built) only
  // when what decides them changed, as a volume's own programs are (UpdatePrograms).
  std::vector<vtkTiledRayCastGroupTraversal::Inputs> inputs;
  for (vtkTiledRayCastGroupMember* member : members)
  {
    inputs.push_back(member->GetGroupInputs());
  }
  if (this->Compute.GroupProgramsChanged(inputs))
  {
    std::vector<vtkTiledRayCastComputePipeline::Replacements> code;
    for (vtkTiledRayCastGroupMember* member : members)
    {
      code.push_back(member->GetGroupCode());
    }
    vtkTiledRayCastStatistics* stats = this->Self->Statistics;
    stats->SetNumberOfShaderCompositions(stats->GetNumberOfShaderCompositions() + 1);
    std::string error;
    if (!this->Compute.UpdateGroupPrograms(window, inputs, code, error))
    {
      this->ReportError(error + " The volumes are drawn one by one.");
      return false;
    }
  }
  // Outside VTK's depth peeling, or in its stage (each built on first use).
  std::string error;
  if (!this->Compute.PrepareGroupStage(this->PeelStage(), error))
  {
    this->ReportError(error + " The volumes are drawn one by one.");
    return false;
  }
  this->Group = members;
  const bool ok = this->DrawFrame(window, rays);
  this->Group.clear();
  return ok;
}

//------------------------------------------------------------------------------
void vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::FinishGroupFrame(int volumes)
{
  this->GroupSize = volumes;
  this->Self->Statistics->SetPipeline("Compute");
  this->Self->FinishRender(0);
  // Which code the traversal held is the drawing mapper's to say.
  this->Self->Statistics->SetGroupCodeShared(false);
}

//------------------------------------------------------------------------------
void vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::WarnGroupOnce(const std::string& text)
{
  if (!this->WarnedGroup)
  {
    vtkWarningWithObjectMacro(this->Self, << text);
    this->WarnedGroup = true;
  }
}

//------------------------------------------------------------------------------
bool vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::BeginDepthOrder(
  vtkRenderer* ren, vtkVolume* vol, bool stage)
{
  if (!stage)
  {
    return true; // drawn one over another into the renderer's framebuffer
  }
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!window)
  {
    return false;
  }
  this->Self->ResourceCallback->RegisterGraphicsResources(window);
  const int peel = this->VolumetricPeel.Update(this->Self, vol);
  if (!this->CheckContext(window) || !this->Context.ComputeSupported ||
    peel < vtkTiledRayCastVolumetricPeel::BeforePeels ||
    peel > vtkTiledRayCastVolumetricPeel::Remainder)
  {
    return false; // each volume draws itself (or is drawn after the peeling)
  }
  // The pass's textures have the viewport's size.
  int width = 0, height = 0, x = 0, y = 0;
  ren->GetTiledSizeAndOrigin(&width, &height, &x, &y);
  std::string error;
  return this->Reported(this->PeelAccumulation.Begin(window, peel, width, height, error), error);
}

//------------------------------------------------------------------------------
void vtkOpenGLTiledRayCastVolumeMapper::vtkInternals::FinishDepthOrder(
  vtkRenderer* ren, vtkVolume* vol, bool stage, int sets)
{
  // After the volume's own draw among the sets, which reset its statistics.
  this->Self->Statistics->SetNumberOfVolumeSetsInDepthOrder(sets);
  if (!stage)
  {
    return;
  }
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  // The volumes drawn since may have asked the pass about themselves: it is asked about this
  // one's stage again, whose textures it binds.
  this->VolumetricPeel.Update(this->Self, vol);
  this->PeelAccumulation.Finish(window, this->VolumetricPeel);
}
