/*=========================================================================

  Program:   TiledRayCast
  Module:    TestHeadlessVolumeSmoke.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// VTK's own volume code runs in the EGL context: vtkProjectedTetrahedraMapper (its OpenGL
// implementation, with its framebuffer objects and shaders) renders the SPX mesh
// (Meshes/spx_vistrails.vtu, 12,936 tets) in an EGL window and matches the baseline.
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkHeadlessEGLRenderWindow.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkProjectedTetrahedraMapper.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderer.h"
#include "vtkTestUtilities.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <cstdlib>
#include <iostream>

int TestHeadlessVolumeSmoke(int argc, char* argv[])
{
  char* fileName = vtkTestUtilities::ExpandDataFileName(argc, argv, "Meshes/spx_vistrails.vtu");
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(fileName);
  delete[] fileName;
  reader->Update();
  if (reader->GetOutput()->GetNumberOfCells() != 12936)
  {
    std::cerr << "cannot read Meshes/spx_vistrails.vtu\n";
    return EXIT_FAILURE;
  }

  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 0.1, 0.2, 1.0);
  color->AddRGBPoint(1.1, 0.2, 1.0, 0.3);
  color->AddRGBPoint(2.254, 1.0, 0.2, 0.1);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.05);
  opacity->AddPoint(1.0, 0.2);
  opacity->AddPoint(2.254, 0.9);
  vtkNew<vtkVolumeProperty> property;
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(0.5);

  vtkNew<vtkProjectedTetrahedraMapper> mapper;
  mapper->SetInputConnection(reader->GetOutputPort());
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);

  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.1, 0.1, 0.1);
  renderer->AddVolume(volume);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Elevation(30.0);
  renderer->ResetCameraClippingRange();
  vtkNew<vtkHeadlessEGLRenderWindow> window;
  window->AddRenderer(renderer);
  window->SetSize(300, 300);
  window->SetMultiSamples(0);

  window->Render();
  if (!window->HasContext() || !mapper->IsSupported(window))
  {
    std::cerr << "vtkProjectedTetrahedraMapper is not supported in the EGL context "
              << window->GetInitializationError() << "\n";
    return EXIT_FAILURE;
  }
  std::cout << "projected tetrahedra on " << window->GetGLRenderer() << ": "
            << mapper->GetTimeToDraw() << " s\n";

  int retVal = vtkRegressionTestImage(window);
  return !retVal;
}
