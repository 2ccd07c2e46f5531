/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkHeadlessSharedWindowInitializer.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// GLEW first: it refuses to follow another GL header.
#include "vtk_glew.h"

#include "vtkHeadlessSharedWindowInitializer.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"

namespace
{
// vtkOpenGLRenderWindow keeps whether it is initialised (GLEW included) in two protected
// members, which only its own OpenGLInitContext() sets. A pointer to a member named through a
// derived class is the way standard C++ gives to reach them from outside (this class is never
// instantiated); nothing else of the window is touched.
class vtkInitializationFlags : public vtkOpenGLRenderWindow
{
public:
  static bool vtkOpenGLRenderWindow::*InitializedFlag()
  {
    return &vtkInitializationFlags::Initialized;
  }
  static bool vtkOpenGLRenderWindow::*GlewInitValidFlag()
  {
    return &vtkInitializationFlags::GlewInitValid;
  }
};
}

//------------------------------------------------------------------------------
bool vtkHeadlessSharedWindowInitializer::IsInitialized(vtkOpenGLRenderWindow* window)
{
  return window->*vtkInitializationFlags::InitializedFlag();
}

//------------------------------------------------------------------------------
bool vtkHeadlessSharedWindowInitializer::Initialize(
  vtkOpenGLRenderWindow* window, vtkOpenGLRenderWindow* context, std::string& error)
{
  context->MakeCurrent();
  if (!context->IsCurrent())
  {
    error = "the EGL context cannot be made current";
    return false;
  }
  // Loads the entry points for this context (glvnd's dispatch stubs), then fails in glxewInit()
  // for want of an X display: the GL part is what counts.
  const GLenum result = glewInit();
#ifdef GLEW_ERROR_NO_GLX_DISPLAY
  const bool usable = result == GLEW_OK || result == GLEW_ERROR_NO_GLX_DISPLAY;
#else
  const bool usable = result == GLEW_OK;
#endif
  if (!usable)
  {
    error = std::string("GLEW could not be initialized on the EGL context: ") +
      reinterpret_cast<const char*>(glewGetErrorString(result));
    return false;
  }
  if (!GLEW_VERSION_3_2)
  {
    error = "the EGL context has no OpenGL 3.2";
    return false;
  }
  window->*vtkInitializationFlags::GlewInitValidFlag() = true;
  window->*vtkInitializationFlags::InitializedFlag() = true;
  // As vtkGenericOpenGLRenderWindow::OpenGLInit() around vtkOpenGLRenderWindow's.
  vtkOpenGLState* state = window->GetState();
  state->Reset();
  state->Push();
  window->OpenGLInitState();
  state->Pop();
  return true;
}
