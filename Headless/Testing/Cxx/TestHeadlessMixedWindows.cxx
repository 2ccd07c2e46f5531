/*=========================================================================

  Program:   TiledRayCast
  Module:    TestHeadlessMixedWindows.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Run under xvfb-run. An X window and an EGL window share the main thread: glvnd lets only one of
// GLX and EGL own the current context, so each window must hand the thread over. The windows
// render in turn (X, EGL, X, EGL) and every image must match the one baseline; then the EGL window
// is destroyed while the X context is current and the X window renders once more. Without the
// hand-over, the second X render ends the process with the X error BadAccess.
//
// It also checks the explicit choices with a display present: VTK_DEFAULT_OPENGL_WINDOW and
// vtkHeadlessObjectFactory::SetBackend() select EGL although X is available.
#include "HeadlessTestScene.h"

#include "vtkHeadlessEGLRenderWindow.h"
#include "vtkHeadlessObjectFactory.h"
#include "vtkNew.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"

#include <cstdlib>
#include <cstring>
#include <iostream>

namespace
{
vtkSmartPointer<vtkRenderWindow> NewWindow()
{
  return vtkSmartPointer<vtkRenderWindow>::Take(vtkRenderWindow::New());
}
}

int TestHeadlessMixedWindows(int argc, char* argv[])
{
  if (!vtkHeadlessObjectFactory::HasUsableDisplay())
  {
    std::cerr << "This test runs under xvfb-run: no X display answers\n";
    return EXIT_FAILURE;
  }
  unsetenv("VTK_DEFAULT_OPENGL_WINDOW");

  // Explicit choices win over the display.
  setenv("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow", 1);
  vtkSmartPointer<vtkRenderWindow> egl = NewWindow();
  unsetenv("VTK_DEFAULT_OPENGL_WINDOW");
  if (!egl->IsA("vtkHeadlessEGLRenderWindow"))
  {
    std::cerr << "VTK_DEFAULT_OPENGL_WINDOW=vtkEGLRenderWindow gave " << egl->GetClassName()
              << "\n";
    return EXIT_FAILURE;
  }
  vtkHeadlessObjectFactory::SetBackend("EGL");
  const bool apiChoice = NewWindow()->IsA("vtkHeadlessEGLRenderWindow");
  vtkHeadlessObjectFactory::SetBackend("auto");
  vtkSmartPointer<vtkRenderWindow> x = NewWindow();
  if (!apiChoice || !x->IsA("vtkXOpenGLRenderWindow"))
  {
    std::cerr << "SetBackend(\"EGL\") or the automatic choice with a display went wrong ("
              << x->GetClassName() << ")\n";
    return EXIT_FAILURE;
  }

  HeadlessTestScene::Add(x);
  HeadlessTestScene::Add(egl);
  int passed = 1;
  for (int round = 0; round < 2; ++round)
  {
    x->Render();
    passed &= (vtkRegressionTestImage(x) == vtkTesting::PASSED);
    egl->Render();
    passed &= (vtkRegressionTestImage(egl) == vtkTesting::PASSED);
  }

  // The EGL window goes away while the X context is current; the X window must not notice.
  x->MakeCurrent();
  egl = nullptr;
  x->Render();
  passed &= (vtkRegressionTestImage(x) == vtkTesting::PASSED);
  std::cout << "X and EGL windows took turns on one thread: " << (passed ? "ok" : "FAILED") << "\n";
  return passed ? EXIT_SUCCESS : EXIT_FAILURE;
}
