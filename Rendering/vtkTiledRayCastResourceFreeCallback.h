/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastResourceFreeCallback.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastResourceFreeCallback
 * @brief   releases a mapper's OpenGL resources when its render window goes away
 *
 * vtkOpenGLRenderWindow keeps a set of vtkGenericOpenGLResourceFreeCallback pointers and calls
 * their Release() before its context is destroyed; VTK's own mappers register one through the
 * template in vtkOpenGLResourceFreeCallback.h. Debian's VTK 9.1 does not install that header (the
 * window's header only forward-declares the base class), so this private header provides the
 * base class with the exact layout that libvtkRenderingOpenGL2 was compiled against (a virtual
 * destructor, then Release() and RegisterGraphicsResources(), then the window pointer and the
 * releasing flag) and our own member-function callback on top of it.
 *
 * Not wrapped, not installed: a private header of the module.
 */

#ifndef vtkTiledRayCastResourceFreeCallback_h
#define vtkTiledRayCastResourceFreeCallback_h

#include "vtkOpenGLRenderWindow.h" // For Push/PopContext and (Un)RegisterGraphicsResources

class vtkWindow;

#ifndef vtkOpenGLResourceFreeCallback_h
#define vtkOpenGLResourceFreeCallback_h
// Same declaration as VTK 9.1's Rendering/OpenGL2/vtkOpenGLResourceFreeCallback.h: the window
// calls Release() through this vtable, so neither the order of the virtual functions nor the
// members may change. The include guard is VTK's own so that the two can never both be seen.
class vtkGenericOpenGLResourceFreeCallback
{
public:
  vtkGenericOpenGLResourceFreeCallback() = default;
  virtual ~vtkGenericOpenGLResourceFreeCallback() = default;

  virtual void Release() = 0;
  virtual void RegisterGraphicsResources(vtkOpenGLRenderWindow* rw) = 0;

  bool IsReleasing() { return this->Releasing; }

protected:
  vtkOpenGLRenderWindow* VTKWindow = nullptr;
  bool Releasing = false;
};
#endif

/**
 * Calls `(handler->*method)(window)` with the window's context current when the window releases
 * its graphics resources, or when the handler registers with another window.
 */
template <class T>
class vtkTiledRayCastResourceFreeCallback : public vtkGenericOpenGLResourceFreeCallback
{
public:
  vtkTiledRayCastResourceFreeCallback(T* handler, void (T::*method)(vtkWindow*))
    : Handler(handler)
    , Method(method)
  {
  }

  ~vtkTiledRayCastResourceFreeCallback() override = default;

  void RegisterGraphicsResources(vtkOpenGLRenderWindow* rw) override
  {
    if (this->VTKWindow == rw)
    {
      return;
    }
    // Resources belong to one context: moving to another window releases them in the old one.
    if (this->VTKWindow)
    {
      this->Release();
    }
    this->VTKWindow = rw;
    if (this->VTKWindow)
    {
      this->VTKWindow->RegisterGraphicsResources(this);
    }
  }

  void Release() override
  {
    if (this->VTKWindow && this->Handler && !this->Releasing)
    {
      this->Releasing = true;
      this->VTKWindow->PushContext();
      (this->Handler->*this->Method)(this->VTKWindow);
      this->VTKWindow->UnregisterGraphicsResources(this);
      this->VTKWindow->PopContext();
      this->VTKWindow = nullptr;
      this->Releasing = false;
    }
  }

  vtkOpenGLRenderWindow* GetWindow() const { return this->VTKWindow; }

private:
  T* Handler;
  void (T::*Method)(vtkWindow*);
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastResourceFreeCallback.h
