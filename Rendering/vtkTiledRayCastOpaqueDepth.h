/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastOpaqueDepth.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastOpaqueDepth
 * @brief   the depth of the scene drawn so far, as a texture: opaque geometry ends the rays
 *
 * Capture() blits the depth of the caller's framebuffer (possibly multisampled) into a texture
 * of the same depth format (a depth blit needs the same format on both sides), one depth per
 * ray: at an image sample distance above 1 the nearest of the pixels around the ray. Without a
 * depth buffer the texture holds 1 everywhere. The texture only grows, and is reallocated when
 * the framebuffer's depth format changes.
 *
 * Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastOpaqueDepth_h
#define vtkTiledRayCastOpaqueDepth_h

#include "vtkNew.h" // For vtkNew

#include <string> // For std::string

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class vtkTiledRayCastOpaqueDepth
{
public:
  vtkTiledRayCastOpaqueDepth();
  ~vtkTiledRayCastOpaqueDepth();

  /**
   * The depth of the bound framebuffer's `width` x `height` pixels from `origin` (the
   * viewport), scaled to `imageSize` (the rays). False, with `error` set, when the texture
   * cannot be allocated or the blit fails.
   */
  bool Capture(vtkOpenGLRenderWindow* window, const int origin[2], int width, int height,
    const int imageSize[2], std::string& error);

  /**
   * The texture the passes read (the mapper activates it).
   */
  vtkTextureObject* GetTexture();

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkTiledRayCastOpaqueDepth(const vtkTiledRayCastOpaqueDepth&) = delete;
  void operator=(const vtkTiledRayCastOpaqueDepth&) = delete;

  // The format of the read framebuffer's depth attachment (GL_NONE where it has none).
  static unsigned int ReadFormat();
  // (Re)allocates the texture and its framebuffer where the format or the size asks.
  bool Allocate(
    vtkOpenGLRenderWindow* window, unsigned int format, int width, int height, std::string& error);

  vtkNew<vtkTextureObject> Texture;
  vtkNew<vtkOpenGLFramebufferObject> Framebuffer;
  unsigned int Format = 0;
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastOpaqueDepth.h
