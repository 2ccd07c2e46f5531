/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastGroupTraversal.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastGroupTraversal
 * @brief   the compute program that traverses up to four overlapping volumes in one pass
 *
 * Composes vtkTiledRayCastGroupTraversalCS.glsl from each volume's own GLSL (its common,
 * layout, integration and walk code, as vtkTiledRayCastShaderComposition composes them for
 * that volume, and vtkTiledRayCastGroupMember.glsl) with every trc*, Trc*, TRC_* and in_*
 * identifier of volume k given the suffix _vk, so that the volumes' meshes, transfer functions,
 * rays and uniforms stay apart in one program (GLSL has no namespaces, and a sampler array
 * could not be indexed by a volume index that varies per ray). The traversal's lines marked
 * //TRC::EachMember are repeated per volume ("@" is its index): they call volume k's functions.
 *
 * Member(k) is a program standing for volume k's uniforms by their plain names
 * (vtkTiledRayCastMemberUniforms): the volume's mapper sets them with its usual setters.
 *
 * Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastGroupTraversal_h
#define vtkTiledRayCastGroupTraversal_h

#include "vtkNew.h"                           // For vtkNew
#include "vtkTiledRayCastShaderComposition.h" // For vtkTiledRayCastGroupComposition

#include <string>  // For std::string
#include <utility> // For std::pair
#include <vector>  // For std::vector

class vtkShaderProgram;
class vtkTiledRayCastComputeShader;
class vtkTiledRayCastMemberUniforms;

class vtkTiledRayCastGroupTraversal
{
public:
  vtkTiledRayCastGroupTraversal();
  ~vtkTiledRayCastGroupTraversal();

  static constexpr int MaximumMembers = 4;
  using Replacements = std::vector<std::pair<std::string, std::string>>;

  using Inputs = vtkTiledRayCastShaderComposition::Inputs;

  /**
   * Build (or keep) the program for these volumes: `members[k]` is volume k's
   * //TRC::Common::Dec, //TRC::Layout::Dec and //TRC::Integration::Dec code, composed from
   * `inputs[k]`, `version` the program's first lines. False with a message when it does not
   * build.
   */
  bool Update(const std::vector<Inputs>& inputs, const std::vector<Replacements>& members,
    const std::string& version, std::string& error);

  /**
   * Whether the program (and the group's raster programs, built with it) is to be built for
   * volumes of these inputs: false when it was last built for them.
   */
  bool Changed(const std::vector<Inputs>& inputs) const
  {
    return this->Composition.Changed(inputs);
  }
  void Invalidate() { this->Composition.Reset(); }

  vtkTiledRayCastComputeShader* GetProgram();

  /**
   * Volume k's uniforms, by their plain names, but for in_opaqueDepth: the volumes share the
   * scene's depth, which the caller sets on the program as in_opaqueDepth_vk.
   */
  vtkShaderProgram* Member(int k);

  /**
   * Identifiers of `code` given `suffix` (trc*, Trc*, TRC_* and in_*); public for the tests.
   */
  static std::string Rename(const std::string& code, const std::string& suffix);

  /**
   * `code` with each line that starts with //TRC::EachMember repeated `count` times, "@"
   * replaced by 0, 1, ...
   */
  static std::string Expand(const std::string& code, int count);

  void ReleaseGraphicsResources();

private:
  vtkTiledRayCastGroupTraversal(const vtkTiledRayCastGroupTraversal&) = delete;
  void operator=(const vtkTiledRayCastGroupTraversal&) = delete;

  vtkNew<vtkTiledRayCastComputeShader> Program;
  vtkNew<vtkTiledRayCastMemberUniforms> Members[MaximumMembers];
  int NumberOfMembers = 0;
  vtkTiledRayCastGroupComposition Composition;
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastGroupTraversal.h
