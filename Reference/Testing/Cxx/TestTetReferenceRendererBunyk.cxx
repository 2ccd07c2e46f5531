/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTetReferenceRendererBunyk.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The reference renderer against VTK's own vtkUnstructuredGridVolumeRayCastMapper (Bunyk's ray
// caster with partial pre-integration, the same optical model) on three datasets, rendered
// offscreen in a VTK window (needs X: run under xvfb-run; skipped without DISPLAY).
//
// Alignment. Bunyk casts its rays through pixel corners (window coordinate k = NDC 2k/W - 1),
// stores floor(255 C) in an 8-bit texture and draws that texture over the viewport with texel
// centres 0 and W-1 at the viewport's edges, bilinearly: screen pixel i shows the corner image
// at (i + 1/2)(W - 1)/W. The reference is rendered at the corners (SampleOffset 0, 0) and put
// through the same floor, stretch and rounding (EmulateRayCastImageDisplay), so that what
// remains is the integration. Both are composited over black.
//
// Bounds: RMSE <= 0.75, 99.9th percentile <= 3, max <= 8 (1/255 units; measured about 0.2 to
// 0.3, 1 and 2). A reference with wrong units (the unit distance doubled) must exceed them:
// checked below, so the comparison can fail.
#include "TetReferenceTestUtilities.h"
#include "TiledRayCastSharedScenes.h"

#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTestUtilities.h"
#include "vtkTetReferenceRenderer.h"
#include "vtkTimerLog.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkWindowToImageFilter.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <cstdlib>
#include <string>

int TestTetReferenceRendererBunyk(int argc, char* argv[])
{
  if (!getenv("DISPLAY"))
  {
    std::cout << "No DISPLAY: this test needs an X server (run it under xvfb-run)." << std::endl;
    return 125; // skipped
  }
  const int size = 128;
  const char* datasets[] = { "spx_vistrails.vtu", "bluntfin_tets.vtu", "torus_tetgen_100k.vtu" };
  for (const char* name : datasets)
  {
    char* path =
      vtkTestUtilities::ExpandDataFileName(argc, argv, (std::string("Meshes/") + name).c_str());
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(path);
    delete[] path;
    reader->Update();
    vtkUnstructuredGrid* grid = reader->GetOutput();
    TRC_CHECK(grid->GetNumberOfCells() > 0);
    double range[2];
    grid->GetPointData()->GetScalars()->GetRange(range);
    double bounds[6];
    grid->GetBounds(bounds);
    // The scene of the comparison, shared with BenchmarkReferenceRenderer.
    vtkSmartPointer<vtkVolumeProperty> property =
      trcscene::MakeBunykProperty(range, trcscene::Diagonal(bounds));
    vtkSmartPointer<vtkVolume> volume = trcscene::MakeBunykVolume(grid, property);
    vtkNew<vtkRenderer> renderer;
    renderer->AddVolume(volume);
    renderer->SetBackground(0, 0, 0);
    vtkNew<vtkRenderWindow> window;
    window->SetOffScreenRendering(1);
    window->AddRenderer(renderer);
    window->SetSize(size, size);
    renderer->ResetCamera();
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->Azimuth(30.0);
    camera->Elevation(20.0);
    camera->Zoom(1.3);
    renderer->ResetCameraClippingRange();
    vtkNew<vtkTimerLog> timer;
    timer->StartTimer();
    window->Render();
    timer->StopTimer();
    const double bunykTime = timer->GetElapsedTime();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    grab->ReadFrontBufferOff();
    grab->SetInputBufferTypeToRGB();
    grab->Update();
    vtkImageData* bunyk = grab->GetOutput();

    vtkNew<vtkTetReferenceRenderer> reference;
    reference->SetInputData(grid);
    reference->SetVolumeProperty(property);
    reference->SetCamera(camera);
    reference->SetImageSize(size, size);
    const double black[3] = { 0, 0, 0 };

    // As the project renders (pixel centres), for information.
    timer->StartTimer();
    TRC_CHECK(reference->Render());
    timer->StopTimer();
    vtkNew<vtkImageData> centres;
    vtkTetReferenceRenderer::ConvertToUnsignedChar(reference->GetOutput(), black, centres);
    double raw[3];
    TRC_CHECK(vtkTetReferenceRenderer::CompareImages(centres, bunyk, raw));

    // Aligned with Bunyk's rays and display.
    reference->SetSampleOffset(0.0, 0.0);
    TRC_CHECK(reference->Render());
    vtkNew<vtkImageData> aligned;
    vtkTetReferenceRenderer::EmulateRayCastImageDisplay(reference->GetOutput(), black, aligned);
    double stats[3];
    TRC_CHECK(vtkTetReferenceRenderer::CompareImages(aligned, bunyk, stats));
    std::cout << name << " (" << grid->GetNumberOfCells() << " tets, " << size << "^2): Bunyk "
              << bunykTime << " s, reference " << timer->GetElapsedTime()
              << " s. Difference, pixel centres: RMSE " << raw[0] << ", p99.9 " << raw[1]
              << ", max " << raw[2] << "; aligned: RMSE " << stats[0] << ", p99.9 " << stats[1]
              << ", max " << stats[2] << " (1/255)" << std::endl;
    TRC_CHECK(stats[0] <= 0.75 && stats[1] <= 3.0 && stats[2] <= 8.0);

    // The comparison must be able to fail: wrong units (twice the unit distance).
    vtkNew<vtkVolumeProperty> wrong;
    wrong->DeepCopy(property);
    wrong->SetScalarOpacityUnitDistance(2.0 * property->GetScalarOpacityUnitDistance());
    reference->SetVolumeProperty(wrong);
    TRC_CHECK(reference->Render());
    vtkTetReferenceRenderer::EmulateRayCastImageDisplay(reference->GetOutput(), black, aligned);
    double broken[3];
    TRC_CHECK(vtkTetReferenceRenderer::CompareImages(aligned, bunyk, broken));
    std::cout << "  with the unit distance doubled: RMSE " << broken[0] << ", p99.9 " << broken[1]
              << ", max " << broken[2] << std::endl;
    TRC_CHECK(broken[0] > 0.75 || broken[1] > 3.0 || broken[2] > 8.0);
  }
  std::cout << "TestTetReferenceRendererBunyk passed" << std::endl;
  return EXIT_SUCCESS;
}
