/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkHeadlessSharedWindowInitializer.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkHeadlessSharedWindowInitializer
 * @brief   private: initialises a window of ParaView's that renders on an EGL window's context
 *
 * ParaView's server-side view windows (a vtkGenericOpenGLRenderWindow each) render on the
 * context of the process's window. Their first render initialises them like any
 * vtkOpenGLRenderWindow, through OpenGLInitContext(), which treats GLEW's refusal of a context
 * that is not GLX (Debian's GLEW is the GLX flavour: GLEW_ERROR_NO_GLX_DISPLAY, after every GL
 * entry point was loaded) as fatal, prints "GLEW could not be initialized" and tries again at
 * every render. On the EGL process window of vtkHeadlessEGLRenderWindow that happens to every
 * view. This does what OpenGLInitContext() and OpenGLInitState() do, on that context, accepting
 * that one code, as vtkHeadlessEGLRenderWindow does for itself.
 */

#ifndef vtkHeadlessSharedWindowInitializer_h
#define vtkHeadlessSharedWindowInitializer_h

#include <string> // For std::string

class vtkOpenGLRenderWindow;

class vtkHeadlessSharedWindowInitializer
{
public:
  /**
   * Whether `window` has been initialised (by itself or by Initialize()).
   */
  static bool IsInitialized(vtkOpenGLRenderWindow* window);

  /**
   * Makes `context`'s context current and initialises `window`, which renders on it. Returns
   * false, with the reason in `error`, when the context cannot be made current or GLEW finds no
   * OpenGL 3.2 there.
   */
  static bool Initialize(
    vtkOpenGLRenderWindow* window, vtkOpenGLRenderWindow* context, std::string& error);
};

#endif
// VTK-HeaderTest-Exclude: vtkHeadlessSharedWindowInitializer.h
