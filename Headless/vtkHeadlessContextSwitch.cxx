/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkHeadlessContextSwitch.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkHeadlessContextSwitch.h"

// The EGL side never needs X types.
#define EGL_NO_X11
#include <EGL/egl.h>

#if TILEDRAYCAST_HEADLESS_HAS_X
#include <GL/glx.h>
#endif

namespace vtkHeadlessContextSwitch
{

bool HasGLX()
{
#if TILEDRAYCAST_HEADLESS_HAS_X
  return true;
#else
  return false;
#endif
}

GLXBinding ReleaseGLX()
{
  GLXBinding binding;
#if TILEDRAYCAST_HEADLESS_HAS_X
  GLXContext context = glXGetCurrentContext();
  if (context)
  {
    Display* display = glXGetCurrentDisplay();
    binding.Display = display;
    binding.DrawDrawable = glXGetCurrentDrawable();
    binding.ReadDrawable = glXGetCurrentReadDrawable();
    binding.Context = context;
    if (display)
    {
      glXMakeContextCurrent(display, None, None, nullptr);
    }
  }
#endif
  return binding;
}

void RestoreGLX(const GLXBinding& binding)
{
#if TILEDRAYCAST_HEADLESS_HAS_X
  if (binding.Context && binding.Display)
  {
    // The caller has released its EGL context first: glvnd refuses GLX otherwise.
    glXMakeContextCurrent(static_cast<Display*>(binding.Display), binding.DrawDrawable,
      binding.ReadDrawable, static_cast<GLXContext>(binding.Context));
  }
#else
  (void)binding;
#endif
}

void ReleaseEGL()
{
  // glvnd answers eglGetCurrentContext() from its thread state, whatever API is bound, and
  // without loading any EGL driver: an X-only program pays nothing here. (eglBindAPI would load
  // the EGL vendor libraries.)
  if (eglGetCurrentContext() != EGL_NO_CONTEXT)
  {
    eglMakeCurrent(eglGetCurrentDisplay(), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
}

}
