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
 * depth buffer the texture holds 1 everywhere (SetFar). The texture only grows, and is
 * reallocated when the framebuffer's depth format changes.
 *
 * Where nothing drawn before the volumes can have written depth (SceneMayHaveDepth), the copy is
 * skipped: the texture is cleared to 1 once and kept so while the scene stays without depth
 * (the copy of a 1024² depth buffer costs about 0.05-0.1 ms of an H200's frame).
 *
 * Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastOpaqueDepth_h
#define vtkTiledRayCastOpaqueDepth_h

#include "vtkNew.h" // For vtkNew

#include <string> // For std::string

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkRenderer;
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
   * Depth 1 (the far plane) for an image of `imageSize` rays, without reading the framebuffer:
   * for a scene without depth (SceneMayHaveDepth). Clears only when the texture held anything
   * else. False, with `error` set, when the texture cannot be allocated.
   */
  bool SetFar(vtkOpenGLRenderWindow* window, const int imageSize[2], std::string& error);

  /**
   * Whether the depth buffer may hold anything but the clear value when `renderer` draws its
   * volumes: it keeps depth from earlier renderers (PreserveDepthBuffer, or no Erase), or one
   * of its visible props other than volumes and foreground 2D actors may draw opaque or
   * translucent geometry (conservatively: any prop not known to be depth-free).
   */
  static bool SceneMayHaveDepth(vtkRenderer* renderer);

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
  bool HoldsFar = false; // every texel is 1 (SetFar cleared it, nothing was blitted since)
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastOpaqueDepth.h
