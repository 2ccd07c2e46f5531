/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkOpenGLTiledRayCastVolumeMapper.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkOpenGLTiledRayCastVolumeMapper
 * @brief   OpenGL implementation of vtkTiledRayCastVolumeMapper
 *
 * What vtkTiledRayCastVolumeMapper::New() returns through VTK's object factory. Every OpenGL
 * object lives in a private implementation class; this header includes no GL header, so the
 * class wraps into Python. See vtkTiledRayCastVolumeMapper for the algorithm and docs/design.md
 * for the conventions.
 *
 * Needs an OpenGL 3.3 core context (or 3.2 with
 * ARB_explicit_attrib_location); without one, Render() reports an error and draws nothing.
 */

#ifndef vtkOpenGLTiledRayCastVolumeMapper_h
#define vtkOpenGLTiledRayCastVolumeMapper_h

#include "vtkRenderingTiledRayCastModule.h" // For export macro
#include "vtkTiledRayCastVolumeMapper.h"

class vtkGenericOpenGLResourceFreeCallback;
class vtkRenderWindow;

class VTKRENDERINGTILEDRAYCAST_EXPORT vtkOpenGLTiledRayCastVolumeMapper
  : public vtkTiledRayCastVolumeMapper
{
public:
  static vtkOpenGLTiledRayCastVolumeMapper* New();
  vtkTypeMacro(vtkOpenGLTiledRayCastVolumeMapper, vtkTiledRayCastVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * WARNING: INTERNAL METHOD - NOT INTENDED FOR GENERAL USE
   * Render the volume.
   */
  void Render(vtkRenderer* ren, vtkVolume* vol) override;

  /**
   * WARNING: INTERNAL METHOD - NOT INTENDED FOR GENERAL USE
   * Release every OpenGL object of the mapper (textures, buffers, framebuffers, queries,
   * timers) in the given window's context. Rendering again afterwards re-creates them.
   */
  void ReleaseGraphicsResources(vtkWindow* window) override;

  /**
   * Whether the window's OpenGL context has what the mapper needs. The window must have been
   * rendered (its context created) at least once.
   */
  static bool IsSupported(vtkRenderWindow* window);

  /**
   * See vtkTiledRayCastVolumeMapper::IsRenderSupported.
   */
  int IsRenderSupported(vtkRenderWindow* window, vtkVolumeProperty* property) override;

protected:
  // Statistics every rendered frame ends with (memory, CPU time).
  void FinishRender(vtkIdType renderTargetBytes);

  vtkOpenGLTiledRayCastVolumeMapper();
  ~vtkOpenGLTiledRayCastVolumeMapper() override;

  class vtkInternals;
  vtkInternals* Impl;
  vtkGenericOpenGLResourceFreeCallback* ResourceCallback;

private:
  vtkOpenGLTiledRayCastVolumeMapper(const vtkOpenGLTiledRayCastVolumeMapper&) = delete;
  void operator=(const vtkOpenGLTiledRayCastVolumeMapper&) = delete;
};

#endif
