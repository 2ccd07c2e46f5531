/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTiledRayCastFactoryWithoutAutoInit.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// A program built without vtk_module_autoinit(), as a user's may be. The abstract mapper and its
// OpenGL implementation behave as VTK's own pairs (vtkGPUVolumeRayCastMapper and
// vtkOpenGLGPUVolumeRayCastMapper): the abstract New() returns what a registered object factory
// makes, and none is registered until the program registers TiledRayCast::RenderingTiledRayCast's,
// which VTK_MODULE_INIT(vtkRenderingTiledRayCast) does at start-up (here called explicitly so that
// the test sees both states); the OpenGL class itself needs no factory.
#include "vtkAutoInit.h"
#include "vtkOpenGLTiledRayCastVolumeMapper.h"
#include "vtkOutputWindow.h"
#include "vtkSmartPointer.h"
#include "vtkTiledRayCastVolumeMapper.h"

#include <cstdlib>
#include <cstring>
#include <iostream>

// What VTK_MODULE_INIT(vtkRenderingTiledRayCast) calls from a static initialiser.
VTK_AUTOINIT_DECLARE(vtkRenderingTiledRayCast)

namespace
{
bool Check(bool condition, const char* what)
{
  if (!condition)
  {
    std::cerr << "check failed: " << what << std::endl;
  }
  return condition;
}
}

int main()
{
  bool ok = true;

  // No factory yet: VTK's abstract New() warns and returns null (the warning is expected here).
  vtkOutputWindow::GetInstance()->SetDisplayModeToNever();
  vtkSmartPointer<vtkTiledRayCastVolumeMapper> none =
    vtkSmartPointer<vtkTiledRayCastVolumeMapper>::Take(vtkTiledRayCastVolumeMapper::New());
  vtkOutputWindow::GetInstance()->SetDisplayModeToDefault();
  ok = Check(none == nullptr, "the abstract New() is null before the factory is registered") && ok;

  // The OpenGL class is concrete: its New() needs no factory.
  auto direct = vtkSmartPointer<vtkOpenGLTiledRayCastVolumeMapper>::New();
  ok = Check(direct != nullptr, "vtkOpenGLTiledRayCastVolumeMapper::New()") && ok;

  // Registered as VTK_MODULE_INIT would: the abstract New() returns the OpenGL mapper.
  VTK_AUTOINIT_CONSTRUCT(vtkRenderingTiledRayCast)
  vtkSmartPointer<vtkTiledRayCastVolumeMapper> mapper =
    vtkSmartPointer<vtkTiledRayCastVolumeMapper>::Take(vtkTiledRayCastVolumeMapper::New());
  ok = Check(mapper != nullptr &&
           std::strcmp(mapper->GetClassName(), "vtkOpenGLTiledRayCastVolumeMapper") == 0,
         "the abstract New() returns the OpenGL mapper once the factory is registered") &&
    ok;

  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
