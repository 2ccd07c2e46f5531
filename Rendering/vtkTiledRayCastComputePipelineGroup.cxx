/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastComputePipelineGroup.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkTiledRayCastComputePipeline's programs and uniforms for a group of overlapping volumes
// traversed together (vtkTiledRayCastGroupTraversal): its own file so that the pipeline's stays
// under ~800 lines.
#include "vtkTiledRayCastComputePipeline.h"

#include "vtkShaderProgram.h"
#include "vtkTiledRayCastComputeShader.h"

#include "vtkTiledRayCastBoundaryFaceFS.h"
#include "vtkTiledRayCastBoundaryFaceVS.h"
#include "vtkTiledRayCastCompositeFS.h"
#include "vtkTiledRayCastNearSliceFS.h"
#include "vtkTiledRayCastNearSliceGS.h"
#include "vtkTiledRayCastNearSliceVS.h"
#include "vtkTiledRayCastQuadVS.h"

#include <string>

//------------------------------------------------------------------------------
bool vtkTiledRayCastComputePipeline::UpdateGroupPrograms(vtkOpenGLRenderWindow* window,
  const std::vector<vtkTiledRayCastGroupTraversal::Inputs>& inputs,
  const std::vector<Replacements>& members, std::string& error)
{
  this->Group.Invalidate(); // until every program is built
  if (members.size() > static_cast<size_t>(vtkTiledRayCastGroupTraversal::MaximumMembers))
  {
    error = "A group of overlapping volumes has at most " +
      std::to_string(vtkTiledRayCastGroupTraversal::MaximumMembers) + " volumes.";
    return false;
  }
  for (size_t k = 0; k < members.size(); ++k)
  {
    const Replacements replacements = ProgramReplacements(members[k], true);
    if (!this->ReadyRaster(window, this->GroupFaces[k],
          Substituted(vtkTiledRayCastBoundaryFaceVS, replacements),
          Substituted(vtkTiledRayCastBoundaryFaceFS, replacements), std::string(), error) ||
      !this->ReadyRaster(window, this->GroupSlices[k],
        Substituted(vtkTiledRayCastNearSliceVS, replacements),
        Substituted(vtkTiledRayCastNearSliceFS, replacements),
        Substituted(vtkTiledRayCastNearSliceGS, replacements), error))
    {
      return false;
    }
  }
  const Replacements replacements = ProgramReplacements(members.front(), true);
  if (!this->ReadyRaster(window, this->CompositeProgram,
        Substituted(vtkTiledRayCastQuadVS, replacements),
        Substituted(vtkTiledRayCastCompositeFS, replacements), std::string(), error))
  {
    return false;
  }
  return this->Group.Update(inputs, members,
    "#version 430 core\n#define TRC_ENTRY_LIST\n#define TRC_GROUP_ENTRIES\n", error);
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastComputePipeline::PrepareGroupStage(int stage, std::string& error)
{
  return this->Group.Prepare(stage, error);
}

//------------------------------------------------------------------------------
void vtkTiledRayCastComputePipeline::SetGroupUniforms(const Frame& frame)
{
  // Each volume's own uniforms, by its own setters, under its suffix; then what they share.
  vtkTiledRayCastComputeShader* traversal = this->Group.GetProgram(frame.PeelStage);
  for (size_t k = 0; k < frame.Members.size(); ++k)
  {
    vtkShaderProgram* member = this->Group.Member(frame.PeelStage, static_cast<int>(k));
    vtkTiledRayCastProgramSetup* setup = frame.Members[k].Setup;
    setup->SetFrameUniforms(member);
    setup->SetMeshUniforms(member);
    setup->SetIntegrationUniforms(member);
    // A lone volume's walk stops where the group's rays stop (the first volume's threshold).
    member->SetUniformf("in_earlyTerminationOpacity", frame.EarlyTerminationOpacity);
  }
  // The scene's depth, which the volumes share.
  traversal->SetUniformi("in_opaqueDepth", frame.OpaqueDepthUnit);
  traversal->SetUniformf("in_groupEarlyTermination", frame.EarlyTerminationOpacity);
}
