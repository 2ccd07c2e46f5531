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
  }
  int width = 0, height = 0;
  ren->GetTiledSizeAndOrigin(&width, &height, &this->Viewport[0], &this->Viewport[1]);
  this->Viewport[2] = width;
  this->Viewport[3] = height;
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
  this->MeshTextures.ActivateTextures(activate);
  this->Integration.ActivateTextures(this->IntegrationMode(), activate);
  this->VisibleMesh.ActivateTextures(activate);
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
