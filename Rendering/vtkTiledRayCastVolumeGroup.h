/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastVolumeGroup.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastVolumeGroup
 * @brief   overlapping volumes of tiled ray-cast mappers, drawn together in one traversal
 *
 * VTK draws a renderer's volumes one after another; where two overlap, compositing one over
 * the other is wrong. Volumes of this module's mappers (compute pipeline, composite blending)
 * whose world bounds overlap, directly or through others, form a group: the first of them whose
 * mapper VTK calls in a frame draws them all in one traversal
 * (vtkTiledRayCastGroupTraversal: each volume's entries in one list, its segments merged in
 * depth order with the others', their mixture integrated where they overlap), and marks the
 * others drawn for this frame of the renderer, so that their mappers draw nothing. Each
 * volume still prepares its own mesh, transfer function and textures (its mapper's work,
 * only what changed).
 *
 * What a group does not take (the fragment pipeline, other blend modes or integrations, the
 * paper's layout, clipping planes, shading, gradient opacity) is drawn on its own as before,
 * with one warning per mapper. One traversal takes as many volumes as the GPU's compute shader
 * has texture units for (vtkTiledRayCastGroupTraversal::GetTextureUnits: 7 volumes of one
 * texture buffer per array in the 32 units of an H100 or of llvmpipe), up to eight; the
 * volumes past that are drawn apart (together, where they overlap one another), each with a
 * warning.
 *
 * Inside VTK's dual depth peeling, which draws every volume in each of its stages, the group is
 * drawn in each stage between the stage's depths, and its other volumes are marked drawn for
 * that stage only.
 *
 * Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastVolumeGroup_h
#define vtkTiledRayCastVolumeGroup_h

#include "vtkTiledRayCastComputePipeline.h" // For the pipeline's Member and Replacements

#include <string> // For std::string
#include <vector> // For std::vector

class vtkOpenGLRenderWindow;
class vtkRenderer;
class vtkTiledRayCastVolumeMapper;
class vtkVolume;

/**
 * What a group needs of one volume's mapper (its internals implement it).
 */
class vtkTiledRayCastGroupMember : public vtkTiledRayCastProgramSetup
{
public:
  /**
   * Empty where this volume can be traversed with others, else what stops it (a phrase: "it
   * uses shading"). Before its frame is prepared, from the mapper's settings; after, also what
   * its frame found.
   */
  virtual std::string GetGroupRefusal(vtkVolume* volume, bool prepared) = 0;

  /**
   * The CPU work of the volume's frame (its mapper's PrepareFrame, without per-pixel targets
   * unless it draws the group); `rays` is the group's image size, set by the first volume.
   * False when the volume draws nothing.
   */
  virtual bool PrepareGroupFrame(vtkRenderer* renderer, vtkVolume* volume,
    vtkOpenGLRenderWindow* window, bool draws, int rays[2]) = 0;

  /**
   * What decides the volume's GLSL (the group's programs are composed again only when it
   * changes), the GLSL (//TRC::Common::Dec, //TRC::Layout::Dec, //TRC::Integration::Dec) and
   * what its entry pass draws.
   */
  virtual vtkTiledRayCastShaderComposition::Inputs GetGroupInputs() = 0;
  virtual vtkTiledRayCastComputePipeline::Replacements GetGroupCode() = 0;
  virtual vtkTiledRayCastComputePipeline::Member GetGroupMember() = 0;

  /**
   * The texture units the volumes of a group drawn by this volume's mapper may take, all
   * together (vtkTiledRayCastGroupTraversal::GetTextureUnits each): what one traversal's compute
   * shader may read and what the window has free, less what the group shares.
   */
  virtual int GetGroupTextureUnits() = 0;

  /**
   * The volume's textures (mesh, transfer function, visible tets), for the group's programs.
   */
  virtual void ActivateGroupTextures(bool activate) = 0;

  /**
   * Draws the group (the first volume's mapper): `members` includes this one, first.
   */
  virtual bool DrawGroup(vtkOpenGLRenderWindow* window, const int rays[2],
    const std::vector<vtkTiledRayCastGroupMember*>& members) = 0;

  /**
   * The statistics of a volume drawn by another's mapper.
   */
  virtual void FinishGroupFrame(int volumes) = 0;

  /**
   * A warning, once per mapper.
   */
  virtual void WarnGroupOnce(const std::string& text) = 0;

  /**
   * Where this volume's mapper draws several sets of volumes in depth order
   * (RenderInDepthOrder), before and after the sets. Inside a stage of VTK's dual depth peeling
   * (`stage`), Begin makes the stage's accumulation active (vtkTiledRayCastPeelAccumulation),
   * or returns false where the sets cannot be put in order there (each volume then draws
   * itself), and Finish composites it into the pass's targets. Finish also says how many sets
   * were drawn (the statistics).
   */
  virtual bool BeginDepthOrder(vtkRenderer* renderer, vtkVolume* volume, bool stage) = 0;
  virtual void FinishDepthOrder(vtkRenderer* renderer, vtkVolume* volume, bool stage, int sets) = 0;
};

class vtkTiledRayCastVolumeGroup
{
public:
  static constexpr int MaximumVolumes = vtkTiledRayCastGroupTraversal::MaximumMembers;

  struct Candidate
  {
    vtkVolume* Volume = nullptr;
    vtkTiledRayCastGroupMember* Member = nullptr;
  };

  /**
   * The group of `self` among the visible volumes of our mappers in a renderer (`candidates`,
   * in the renderer's order, `self` among them): the volumes that can be traversed together
   * and overlap `self` directly or through others, `self` first. A single volume (itself) where
   * it overlaps none, cannot be grouped, or the group would have more than MaximumVolumes
   * (warned once per mapper). Render() then takes what the texture units hold.
   */
  static std::vector<Candidate> Select(const std::vector<Candidate>& candidates, vtkVolume* self);

  /**
   * Draws the group (`group[0]`'s mapper draws) and marks its other volumes drawn for this frame
   * of the renderer. The number of volumes drawn together, or 0 when the first volume should
   * draw alone (the others then draw themselves).
   */
  static int Render(
    vtkRenderer* renderer, vtkOpenGLRenderWindow* window, const std::vector<Candidate>& group);

  /**
   * Whether `volume` was drawn in this frame of `renderer` by another volume's mapper (inside
   * VTK's depth peeling: in its current stage; the call consumes that mark).
   */
  static bool WasDrawn(vtkRenderer* renderer, vtkVolume* volume);

  /**
   * Draws every volume of `candidates` (the visible volumes of our mappers in `renderer`;
   * `self`, among them, is the one whose mapper VTK calls first) in depth order, farthest first
   * (vtkTiledRayCastVolumeOrder): each group of overlapping volumes as one, in one traversal, and
   * each other volume alone, all through vtkVolume::RenderVolumetricGeometry as VTK would draw
   * them, then marks them drawn for this frame. Inside VTK's dual depth peeling it does so in
   * each stage, between the stage's depths: the sets go over one another in `self`'s mapper's
   * accumulation (BeginStageInDepthOrder), composited into the pass's targets once. Volumes
   * wholly outside the camera's frustum are left to VTK (which culls them). True when it drew
   * them; false, to draw only the calling volume as usual, when there is nothing to order
   * (fewer than two sets in view), when called again from a volume it is drawing, or where the
   * stage cannot take them in order.
   */
  static bool RenderInDepthOrder(
    vtkRenderer* renderer, const std::vector<Candidate>& candidates, vtkVolume* self);

  /**
   * Why `mapper`'s `volume` cannot be traversed with others (a phrase), or empty: the mapper's
   * settings, whether its context lacks compute shaders, and whether its frame found shading
   * or gradient opacity in force.
   */
  static std::string Refusal(
    vtkTiledRayCastVolumeMapper* mapper, vtkVolume* volume, bool noCompute, bool lit);

  /**
   * Whether two volumes' world bounds meet.
   */
  static bool Overlap(vtkVolume* a, vtkVolume* b);

private:
  // Drawn in this frame of the renderer, or only in this stage of VTK's depth peeling (`stage`).
  static void MarkDrawn(vtkRenderer* renderer, vtkVolume* volume, bool stage = false);
  // Whether it is marked so (the mark is not taken).
  static bool Marked(vtkRenderer* renderer, vtkVolume* volume);
  // Whether `set` (a group Select() found) may be more than one traversal takes (Render()
  // then draws the volumes left out apart).
  static bool MaySplit(const std::vector<Candidate>& set, const Candidate& drawer);
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastVolumeGroup.h
