/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkHeadlessXOpenGLRenderWindow.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkHeadlessXOpenGLRenderWindow
 * @brief   VTK's X11 window, made safe to share a thread with EGL windows
 *
 * glvnd lets only one window-system API own the current context of a thread. VTK's
 * vtkXOpenGLRenderWindow calls glXMakeCurrent whenever its context is not current; if an EGL
 * context (a vtkHeadlessEGLRenderWindow's) is current at that moment, glvnd raises the X error
 * BadAccess and Xlib's default error handler ends the process. This subclass releases any
 * current EGL context before the X window binds its own; it changes nothing else.
 *
 * vtkHeadlessObjectFactory returns it from vtkRenderWindow::New() when the X backend is chosen,
 * so mixed X/EGL programs are safe as long as their windows come from vtkRenderWindow::New().
 * A vtkXOpenGLRenderWindow created by name does not have this protection.
 *
 * @sa vtkHeadlessEGLRenderWindow vtkHeadlessObjectFactory
 */

#ifndef vtkHeadlessXOpenGLRenderWindow_h
#define vtkHeadlessXOpenGLRenderWindow_h

#include "vtkRenderingHeadlessModule.h" // For export macro
#include "vtkXOpenGLRenderWindow.h"

class VTKRENDERINGHEADLESS_EXPORT vtkHeadlessXOpenGLRenderWindow : public vtkXOpenGLRenderWindow
{
public:
  static vtkHeadlessXOpenGLRenderWindow* New();
  vtkTypeMacro(vtkHeadlessXOpenGLRenderWindow, vtkXOpenGLRenderWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Release a current EGL context first, then do what vtkXOpenGLRenderWindow does.
   */
  void Initialize() override;
  void Finalize() override;
  void Start() override;
  void Render() override;
  void MakeCurrent() override;
  void PushContext() override;
  ///@}

protected:
  vtkHeadlessXOpenGLRenderWindow();
  ~vtkHeadlessXOpenGLRenderWindow() override;

private:
  vtkHeadlessXOpenGLRenderWindow(const vtkHeadlessXOpenGLRenderWindow&) = delete;
  void operator=(const vtkHeadlessXOpenGLRenderWindow&) = delete;
};

#endif
