/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastGroupTraversal.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastGroupTraversal
 * @brief   the compute programs that traverse several overlapping volumes in one pass
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

  // The most volumes one program is composed for (each volume's state is in registers: past
  // about seven a GPU spills them). What a GPU takes is bounded first by its compute shader's
  // samplers (GetTextureUnits).
  static constexpr int MaximumMembers = 8;
  // The fewest volumes that share one copy of the member code (vtkTiledRayCastSharedMemberCode)
  // where their code is the same. Measured on an H100 at 1024^2 (docs/benchmarks.md): three
  // copies of a mesh draw faster with it in five of six scenes (two meshes 1.7 times, overlapping
  // nearly everywhere), four and seven copies 1.2-1.8 times; two copies are slower with it (up to
  // 1.7 times: choosing the volume's uniforms and samplers costs more than a second event body).
  static constexpr int SharedCodeMembers = 3;
  using Replacements = std::vector<std::pair<std::string, std::string>>;

  using Inputs = vtkTiledRayCastShaderComposition::Inputs;

  /**
   * Compose the programs for these volumes: `members[k]` is volume k's //TRC::Common::Dec,
   * //TRC::Layout::Dec and //TRC::Integration::Dec code, composed from `inputs[k]`, `version`
   * the program's first lines. Each program is built when first asked for (Prepare). False with
   * a message when there are too few or too many volumes.
   */
  bool Update(const std::vector<Inputs>& inputs, const std::vector<Replacements>& members,
    const std::string& version, std::string& error);

  /**
   * Build (or keep) the program of `stage`: 0 outside VTK's dual depth peeling, 1 to 3 its
   * stages (vtkTiledRayCastVolumetricPeel: each volume between the stage's depths, a front and
   * a back colour). False with a message when it does not build.
   */
  bool Prepare(int stage, std::string& error);

  /**
   * Whether the programs (and the group's raster programs, built with them) are to be composed
   * for volumes of these inputs: false when they were last composed for them.
   */
  bool Changed(const std::vector<Inputs>& inputs) const
  {
    return this->Composition.Changed(inputs);
  }
  void Invalidate() { this->Composition.Reset(); }

  vtkTiledRayCastComputeShader* GetProgram(int stage);

  /**
   * Volume k's uniforms in the program of `stage`, by their plain names, but for
   * in_opaqueDepth: the volumes share the scene's depth, which the caller sets on the program.
   * They share the partial pre-integration table (in_psiTable, the same function for every
   * transfer function) too, which volume 0 sets.
   */
  vtkShaderProgram* Member(int stage, int k);

  /**
   * The samplers (texture units) a program of `stage` takes for a volume of these inputs (its
   * mesh's texture buffers, its transfer function, its visible tets), and those the volumes
   * share (the scene's depth, the partial pre-integration table, the stage's depths): a GPU
   * takes as many volumes in one traversal as its compute shader's texture units hold.
   */
  static int GetTextureUnits(const Inputs& inputs);
  static int GetSharedTextureUnits(int stage);

  /**
   * Identifiers of `code` given `suffix` (trc*, Trc*, TRC_* and in_*), but for the uniforms the
   * volumes share; public for the tests.
   */
  static std::string Rename(const std::string& code, const std::string& suffix);

  /**
   * `code` with each line that starts with //TRC::EachMember repeated `count` times, "@"
   * replaced by 0, 1, ...
   */
  static std::string Expand(const std::string& code, int count);

  /**
   * Whether the programs hold one copy of the member code for every volume
   * (vtkTiledRayCastSharedMemberCode: the volumes' code is the same, and shareable).
   */
  bool GetSharedCode() const { return this->SharedCode; }

  void ReleaseGraphicsResources();

private:
  vtkTiledRayCastGroupTraversal(const vtkTiledRayCastGroupTraversal&) = delete;
  void operator=(const vtkTiledRayCastGroupTraversal&) = delete;

  // Outside VTK's depth peeling (0) and in each of its stages (1 to 3): the program, built on
  // first use from Source, and each volume's uniforms in it.
  static constexpr int NumberOfStages = 4;
  struct StageProgram
  {
    vtkNew<vtkTiledRayCastComputeShader> Program;
    vtkNew<vtkTiledRayCastMemberUniforms> Members[MaximumMembers];
    bool Built = false;
  };
  StageProgram Stages[NumberOfStages];
  std::string Source; // every volume's code in place; the version lines not yet
  std::string Version;
  int NumberOfMembers = 0;
  bool SharedCode = false;
  std::vector<std::string> Indexed; // the member uniforms that the shared code made arrays
  vtkTiledRayCastGroupComposition Composition;
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastGroupTraversal.h
