/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastPeelAccumulation.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastPeelAccumulation
 * @brief   several sets of volumes in one stage of VTK's dual depth peeling, in depth order
 *
 * vtkDualDepthPeelingPass draws every volume in each stage of its peeling and blends what each
 * returns into its targets with MAX: two volumes that meet one pixel's range in one stage come
 * out as the brighter of the two, not one over the other. When the renderer holds several sets
 * of this module's volumes (groups of overlapping volumes, each traversed together, and volumes
 * apart), the first of them that a stage draws draws them all, farthest first
 * (vtkTiledRayCastVolumeGroup::RenderInDepthOrder), between Begin() and Finish(): each set's
 * traversal writes its front and back colours as alone, and Add() puts them over the stage's
 * accumulation (vtkTiledRayCastPeelAccumulateCS.glsl) instead of compositing them into the
 * pass's targets; Finish() composites the whole once, as one volume would
 * (vtkTiledRayCastCompositeFS.glsl at the stage, whose textures the pass binds).
 *
 * GPU memory: two RGBA16 targets of the viewport's size (16 B a pixel), allocated the first
 * time a stage draws several sets.
 *
 * Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastPeelAccumulation_h
#define vtkTiledRayCastPeelAccumulation_h

#include "vtkNew.h"  // For vtkNew
#include "vtkType.h" // For vtkIdType

#include <string> // For std::string

class vtkOpenGLRenderWindow;
class vtkOpenGLVertexArrayObject;
class vtkShaderProgram;
class vtkTextureObject;
class vtkTiledRayCastComputeShader;
class vtkTiledRayCastVolumetricPeel;
class vtkWindow;

class vtkTiledRayCastPeelAccumulation
{
public:
  vtkTiledRayCastPeelAccumulation();
  ~vtkTiledRayCastPeelAccumulation();

  /**
   * Start a stage's draw of several sets (`stage`: vtkTiledRayCastVolumetricPeel's 1 to 3) into
   * targets of `width` x `height` (the pass's textures, from their origin): until Finish(), this
   * is the accumulation GetActive() returns. False with a message when the GPU cannot allocate
   * the targets or a program does not build.
   */
  bool Begin(vtkOpenGLRenderWindow* window, int stage, int width, int height, std::string& error);

  /**
   * The accumulation of the stage being drawn, or null (outside Begin() and Finish()).
   */
  static vtkTiledRayCastPeelAccumulation* GetActive();

  /**
   * One set's front and back colours (its traversal's, one ray per pixel from the origin) over
   * what the sets drawn before it left.
   */
  void Add(vtkOpenGLRenderWindow* window, vtkTextureObject* color, vtkTextureObject* backColor);

  /**
   * Composite the accumulation into the pass's draw buffers (bound by the caller, with the
   * pass's blending) as one volume's colours at this stage, with the textures `peel` binds; no
   * longer active. Nothing is drawn where no set was added.
   */
  void Finish(vtkOpenGLRenderWindow* window, const vtkTiledRayCastVolumetricPeel& peel);

  /**
   * Sets added in the last stage drawn.
   */
  int GetNumberOfSets() const { return this->Sets; }

  /**
   * GPU memory of the targets, in bytes.
   */
  vtkIdType GetBytes() const;

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkTiledRayCastPeelAccumulation(const vtkTiledRayCastPeelAccumulation&) = delete;
  void operator=(const vtkTiledRayCastPeelAccumulation&) = delete;

  bool Allocate(vtkOpenGLRenderWindow* window, int width, int height);

  vtkNew<vtkTextureObject> Color;
  vtkNew<vtkTextureObject> BackColor;
  vtkNew<vtkTiledRayCastComputeShader> Accumulate;
  // Each stage's composite (1 to 3), made on first use; owned by the window's shader cache.
  vtkShaderProgram* Composite[3] = { nullptr, nullptr, nullptr };
  vtkNew<vtkOpenGLVertexArrayObject> CompositeVAO[3];
  int Stage = 0;
  int Size[2] = { 0, 0 };
  int Sets = 0;
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastPeelAccumulation.h
