/*=========================================================================

  Program:   TiledRayCast
  Module:    TestHeadlessXWindow.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Run under xvfb-run. With a usable DISPLAY, a plain vtkRenderWindow::New() must still give VTK's
// X window (through the headless factory), and it must render the test scene exactly as the EGL
// window does: it is compared with the EGL baseline, TestHeadlessEGLWindow.png.
#include "HeadlessTestScene.h"

#include "vtkHeadlessObjectFactory.h"
#include "vtkNew.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"

#include <cstdlib>
#include <iostream>

int TestHeadlessXWindow(int argc, char* argv[])
{
  if (!vtkHeadlessObjectFactory::HasUsableDisplay())
  {
    std::cerr << "This test runs under xvfb-run: no X display answers\n";
    return EXIT_FAILURE;
  }
  unsetenv("VTK_DEFAULT_OPENGL_WINDOW");
  vtkSmartPointer<vtkRenderWindow> window =
    vtkSmartPointer<vtkRenderWindow>::Take(vtkRenderWindow::New());
  if (!window || !window->IsA("vtkXOpenGLRenderWindow"))
  {
    std::cerr << "vtkRenderWindow::New() with a display gave "
              << (window ? window->GetClassName() : "nothing") << ", not an X window\n";
    return EXIT_FAILURE;
  }
  HeadlessTestScene::Add(window);
  window->Render();
  HeadlessTestScene::PrintGL(window, "X window");

  int retVal = vtkRegressionTestImage(window);
  return !retVal;
}
