/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkHeadlessContextSwitch.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @file   vtkHeadlessContextSwitch.h
 * @brief  private: hand a thread over between GLX and EGL contexts
 *
 * glvnd (libGLX, libEGL, libGLdispatch) lets only one window-system API own the current
 * context of a thread. While a GLX context is current, eglMakeCurrent fails with
 * EGL_BAD_ACCESS; while an EGL context is current, glXMakeCurrent raises the X error BadAccess,
 * and Xlib's default handler then exits the process. VTK's X and EGL windows each assume they
 * own the thread, so the headless windows release the other API's context before making their
 * own current, and remember it so that PopContext() can restore it.
 *
 * Not part of the public API: the functions take and return only opaque values so that no GLX
 * or EGL header leaks to the callers.
 */

#ifndef vtkHeadlessContextSwitch_h
#define vtkHeadlessContextSwitch_h

namespace vtkHeadlessContextSwitch
{
/**
 * What was current through GLX on this thread (all null when nothing was).
 */
struct GLXBinding
{
  void* Display = nullptr;
  unsigned long DrawDrawable = 0;
  unsigned long ReadDrawable = 0;
  void* Context = nullptr;
};

/**
 * True when this build knows GLX (Debian's VTK is built with VTK_USE_X).
 */
bool HasGLX();

/**
 * Releases the GLX context current on this thread, if any, and returns what it was.
 */
GLXBinding ReleaseGLX();

/**
 * Makes `binding` current again through GLX (nothing when it holds no context).
 */
void RestoreGLX(const GLXBinding& binding);

/**
 * Releases the desktop-OpenGL EGL context current on this thread, if any, whoever made it.
 */
void ReleaseEGL();
}

#endif
// VTK-HeaderTest-Exclude: vtkHeadlessContextSwitch.h
