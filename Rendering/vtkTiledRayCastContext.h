/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastContext.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastContext
 * @brief   what an OpenGL context allows the mapper: its version line and limits, checked once
 *
 * FragmentPipelineVersion() is the one check of the context's OpenGL version, for the mapper's
 * IsSupported() and for Check(). Check() reads a window's limits once: the mapper asks at every
 * frame, and only another window (or one whose resources were released, Reset()) is read again.
 *
 * Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastContext_h
#define vtkTiledRayCastContext_h

#include <string> // For std::string

class vtkOpenGLRenderWindow;

class vtkTiledRayCastContext
{
public:
  /**
   * The version line of the fragment pipeline's programs (their //TRC::Version tag), or null
   * where the context cannot run them.
   */
  static const char* FragmentPipelineVersion(vtkOpenGLRenderWindow* window);

  /**
   * Whether `window`'s context can run the fragment pipeline (false with Error set), its limits
   * read into the members below. Reads nothing when `window` was the last one checked.
   */
  bool Check(vtkOpenGLRenderWindow* window);

  /**
   * Forget the window checked: the next Check() reads its context again.
   */
  void Reset() { this->Window = nullptr; }

  vtkOpenGLRenderWindow* Window = nullptr; // the window checked last
  bool Usable = false;
  std::string Error;         // why not usable
  std::string VersionHeader; // FragmentPipelineVersion()
  int MaxTextureSize = 0;
  int MaxTextureBufferSize = 0;
  int Max3DTextureSize = 0;
  bool ComputeSupported = false;  // OpenGL 4.3
  int MaxComputeTextureUnits = 0; // a compute shader's samplers (the bound of a group's volumes)
  bool SoftwareRasterizer =
    false; // Mesa's llvmpipe or softpipe, SwiftShader: "GPU" work on the CPU
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastContext.h
