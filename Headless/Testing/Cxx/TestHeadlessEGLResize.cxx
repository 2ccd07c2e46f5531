/*=========================================================================

  Program:   TiledRayCast
  Module:    TestHeadlessEGLResize.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// An EGL window is resized between renders (300x300, 420x180, 160x320, then 360x240). After each
// render the image read back must have the new size, and the sphere of the test scene must stay
// round: its extent in x and y, in pixels, may differ by at most 3 pixels (VTK keeps the aspect
// ratio; a framebuffer that kept its old size would stretch or crop it). The last image is
// compared with a baseline.
#include "HeadlessTestScene.h"

#include "vtkActor.h"
#include "vtkHeadlessEGLRenderWindow.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cstdlib>
#include <iostream>

namespace
{
// Extent (in pixels) of the pixels that are not background.
bool Extent(vtkRenderWindow* window, int width, int height, int& dx, int& dy)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkImageData* image = grab->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  if (dims[0] != width || dims[1] != height)
  {
    std::cerr << "image is " << dims[0] << "x" << dims[1] << ", window " << width << "x" << height
              << "\n";
    return false;
  }
  int xmin = width, xmax = -1, ymin = height, ymax = -1;
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const unsigned char* p = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
      if (p[0] > 40 || p[1] > 40 || p[2] > 40)
      {
        xmin = std::min(xmin, x);
        xmax = std::max(xmax, x);
        ymin = std::min(ymin, y);
        ymax = std::max(ymax, y);
      }
    }
  }
  dx = xmax - xmin + 1;
  dy = ymax - ymin + 1;
  return xmax >= 0;
}
}

int TestHeadlessEGLResize(int argc, char* argv[])
{
  vtkNew<vtkHeadlessEGLRenderWindow> window;
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.0, 0.0, 0.0);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(64);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(1.0, 0.6, 0.2);
  renderer->AddActor(actor);
  window->AddRenderer(renderer);
  window->SetMultiSamples(0);

  const int sizes[][2] = { { 300, 300 }, { 420, 180 }, { 160, 320 }, { 360, 240 } };
  for (const auto& size : sizes)
  {
    window->SetSize(size[0], size[1]);
    renderer->ResetCamera(); // fits the sphere to the new aspect ratio
    window->Render();
    const int* actual = window->GetSize();
    int dx = 0;
    int dy = 0;
    if (actual[0] != size[0] || actual[1] != size[1] || !Extent(window, size[0], size[1], dx, dy))
    {
      std::cerr << "render at " << size[0] << "x" << size[1] << " failed\n";
      return EXIT_FAILURE;
    }
    std::cout << size[0] << "x" << size[1] << ": sphere " << dx << "x" << dy << " pixels\n";
    if (std::abs(dx - dy) > 3 || dx < 20)
    {
      std::cerr << "the sphere is not round after resizing\n";
      return EXIT_FAILURE;
    }
  }

  int retVal = vtkRegressionTestImage(window);
  return !retVal;
}
