/*=========================================================================

  Program:   TiledRayCast
  Module:    TestHeadlessEGLWindow.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// An EGL window, created by name with its automatic platform choice (a GPU if there is one, else
// Mesa's surfaceless platform), renders the lit test scene with no X server and matches the
// baseline, with its default 1x1 pbuffer and again without any surface. It must report a core
// profile of OpenGL 3.2 or later and the strings it got.
#include "HeadlessTestScene.h"

#include "vtkHeadlessEGLRenderWindow.h"
#include "vtkNew.h"
#include "vtkRegressionTestImage.h"

#include <iostream>

int TestHeadlessEGLWindow(int argc, char* argv[])
{
  vtkNew<vtkHeadlessEGLRenderWindow> window;
  HeadlessTestScene::Add(window);
  window->Render();

  if (!window->HasContext())
  {
    std::cerr << "No EGL context: " << window->GetInitializationError() << "\n";
    return EXIT_FAILURE;
  }
  HeadlessTestScene::PrintGL(window, "EGL window");
  std::cout << "EGL platform in use: " << window->GetPlatformInUse() << ", device "
            << window->GetDeviceIndexInUse() << "\n"
            << vtkHeadlessEGLRenderWindow::GetDeviceDescriptions();

  // The GPUs among the devices (what a ParaView rank picks from by its local rank): each
  // ordinal names a device, the one past the last none.
  const int gpus = vtkHeadlessEGLRenderWindow::GetNumberOfGPUDevices();
  bool gpuIndices = gpus <= window->GetNumberOfDevices() &&
    vtkHeadlessEGLRenderWindow::GetGPUDeviceIndex(gpus) == -1 &&
    vtkHeadlessEGLRenderWindow::GetGPUDeviceIndex(-1) == -1;
  for (int ordinal = 0; ordinal < gpus; ++ordinal)
  {
    const int index = vtkHeadlessEGLRenderWindow::GetGPUDeviceIndex(ordinal);
    gpuIndices = gpuIndices && index >= 0 && index < window->GetNumberOfDevices();
  }
  std::cout << gpus << " GPU device(s)\n";
  if (!gpuIndices)
  {
    std::cerr << "GetGPUDeviceIndex() does not agree with GetNumberOfGPUDevices()\n";
    return EXIT_FAILURE;
  }

  int major = 0;
  int minor = 0;
  window->GetOpenGLVersion(major, minor);
  if (major * 10 + minor < 32)
  {
    std::cerr << "OpenGL " << major << "." << minor << " is below 3.2\n";
    return EXIT_FAILURE;
  }
  if (!*window->GetGLRenderer() || !*window->GetGLVersion() || !*window->GetEGLVersion() ||
    !*window->GetPlatformInUse())
  {
    std::cerr << "Unexpected strings: renderer '" << window->GetGLRenderer() << "', version '"
              << window->GetGLVersion() << "', EGL '" << window->GetEGLVersion() << "'\n";
    return EXIT_FAILURE;
  }
  if (window->IsA("vtkXOpenGLRenderWindow") || window->GetShowWindow() || !window->SupportsOpenGL())
  {
    std::cerr << "The EGL window must be an offscreen window that supports OpenGL\n";
    return EXIT_FAILURE;
  }

  int passed = (vtkRegressionTestImage(window) == vtkTesting::PASSED);

  // The same scene in a context without any surface (EGL_KHR_surfaceless_context) instead of
  // the default 1x1 pbuffer: VTK renders into its own framebuffers either way.
  vtkNew<vtkHeadlessEGLRenderWindow> noSurface;
  noSurface->PreferSurfacelessContextOn();
  HeadlessTestScene::Add(noSurface);
  noSurface->Render();
  if (window->GetContextIsSurfaceless() || !noSurface->GetContextIsSurfaceless())
  {
    std::cerr << "expected a pbuffer by default and no surface when asked (this EGL lacks "
                 "EGL_KHR_surfaceless_context?)\n";
    return EXIT_FAILURE;
  }
  passed &= (vtkRegressionTestImage(noSurface) == vtkTesting::PASSED);
  return passed ? EXIT_SUCCESS : EXIT_FAILURE;
}
