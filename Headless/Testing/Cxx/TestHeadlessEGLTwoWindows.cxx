/*=========================================================================

  Program:   TiledRayCast
  Module:    TestHeadlessEGLTwoWindows.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Two EGL windows in one process share one EGL display but have their own contexts. They render
// different scenes in turn; the first must keep matching the baseline of the test scene
// (TestHeadlessEGLWindow.png) and the second must show its own picture. Then the second window
// is destroyed: the display they shared must stay initialized for the first (eglTerminate is
// counted per display), which renders once more and must still match.
#include "HeadlessTestScene.h"

#include "vtkActor.h"
#include "vtkCubeSource.h"
#include "vtkHeadlessEGLRenderWindow.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <cstdlib>
#include <iostream>

namespace
{
// A yellow cube on a black background, 200x120.
void AddCubeScene(vtkRenderWindow* window)
{
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.0, 0.0, 0.0);
  vtkNew<vtkCubeSource> cube;
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(cube->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(1.0, 1.0, 0.0);
  actor->GetProperty()->SetAmbient(1.0);
  actor->GetProperty()->SetDiffuse(0.0);
  renderer->AddActor(actor);
  renderer->ResetCamera();
  window->AddRenderer(renderer);
  window->SetSize(200, 120);
  window->SetMultiSamples(0);
}

// The second window's picture: black corner, yellow centre.
bool CheckCubeImage(vtkRenderWindow* window)
{
  vtkNew<vtkUnsignedCharArray> pixels;
  if (window->GetPixelData(0, 0, 199, 119, 0, pixels, 0) != VTK_OK)
  {
    std::cerr << "cannot read the second window's pixels\n";
    return false;
  }
  const unsigned char* corner = pixels->GetPointer(0);
  const unsigned char* centre = pixels->GetPointer(3 * (60 * 200 + 100));
  const bool ok = corner[0] == 0 && corner[1] == 0 && corner[2] == 0 && centre[0] > 200 &&
    centre[1] > 200 && centre[2] < 30;
  if (!ok)
  {
    std::cerr << "second window: corner " << int(corner[0]) << "," << int(corner[1]) << ","
              << int(corner[2]) << " centre " << int(centre[0]) << "," << int(centre[1]) << ","
              << int(centre[2]) << " (expected black and yellow)\n";
  }
  return ok;
}
}

int TestHeadlessEGLTwoWindows(int argc, char* argv[])
{
  vtkNew<vtkHeadlessEGLRenderWindow> first;
  HeadlessTestScene::Add(first);
  vtkSmartPointer<vtkHeadlessEGLRenderWindow> second =
    vtkSmartPointer<vtkHeadlessEGLRenderWindow>::New();
  AddCubeScene(second);

  int passed = 1;
  for (int round = 0; round < 2; ++round)
  {
    first->Render();
    second->Render();
    passed &= CheckCubeImage(second) ? 1 : 0;
    passed &= (vtkRegressionTestImage(first) == vtkTesting::PASSED);
  }
  if (!first->HasContext() || !second->HasContext() ||
    first->GetGenericContext() == second->GetGenericContext() ||
    first->GetGenericDisplayId() != second->GetGenericDisplayId())
  {
    std::cerr << "expected two contexts on one shared EGL display\n";
    passed = 0;
  }

  second = nullptr; // finalizes its context but must leave the shared display alone
  // Bind the first context again from scratch: on a terminated display eglMakeCurrent fails.
  first->ReleaseCurrent();
  first->Render();
  passed &= (vtkRegressionTestImage(first) == vtkTesting::PASSED);
  return passed ? EXIT_SUCCESS : EXIT_FAILURE;
}
