/*=========================================================================

  Program:   TiledRayCast
  Module:    RenderMesh.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Renders a tetrahedral mesh (.vtu) with vtkTiledRayCastVolumeMapper to a PNG file and prints
// what the mapper did.
//
//   RenderMesh <mesh.vtu> <out.png> [size]
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTetMeshValidationReport.h"
#include "vtkTiledRayCastStatistics.h"
#include "vtkTiledRayCastVolumeMapper.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkWindowToImageFilter.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <cstdlib>
#include <iostream>

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: " << argv[0] << " <mesh.vtu> <out.png> [size]\n";
    return EXIT_FAILURE;
  }
  const int size = argc > 3 ? std::atoi(argv[3]) : 512;

  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(argv[1]);
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  vtkDataArray* scalars = grid->GetPointData()->GetScalars();
  if (!scalars)
  {
    std::cerr << argv[1] << " has no point scalars\n";
    return EXIT_FAILURE;
  }
  double range[2];
  scalars->GetRange(range);

  // A transfer function over the data's range: transparent low values, a bright band higher up.
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(range[0], 0.0);
  opacity->AddPoint(range[0] + 0.5 * (range[1] - range[0]), 0.3);
  opacity->AddPoint(range[1], 0.8);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(range[0], 0.1, 0.2, 0.9);
  color->AddRGBPoint(range[0] + 0.5 * (range[1] - range[0]), 0.9, 0.9, 0.9);
  color->AddRGBPoint(range[1], 0.9, 0.2, 0.1);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  double bounds[6];
  grid->GetBounds(bounds);
  property->SetScalarOpacityUnitDistance(0.05 * (bounds[1] - bounds[0]));

  vtkNew<vtkTiledRayCastVolumeMapper> mapper;
  mapper->SetInputData(grid);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);

  vtkNew<vtkRenderer> renderer;
  renderer->AddVolume(volume);
  renderer->SetBackground(1, 1, 1);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Azimuth(30);
  renderer->GetActiveCamera()->Elevation(20);
  renderer->ResetCameraClippingRange();
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(size, size);
  window->AddRenderer(renderer);
  window->Render();
  if (!mapper->GetStatistics()->GetRendered())
  {
    std::cerr << "nothing was rendered: " << mapper->GetValidationReport()->GetSummary() << "\n";
    return EXIT_FAILURE;
  }

  vtkNew<vtkWindowToImageFilter> capture;
  capture->SetInput(window);
  capture->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(argv[2]);
  writer->SetInputConnection(capture->GetOutputPort());
  writer->Write();

  std::cout << "mesh: " << mapper->GetValidationReport()->GetSummary() << "\n"
            << "render: " << mapper->GetStatistics()->GetSummary() << "\n"
            << "wrote " << argv[2] << "\n";
  return EXIT_SUCCESS;
}
