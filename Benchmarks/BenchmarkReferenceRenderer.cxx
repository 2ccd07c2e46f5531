/*=========================================================================

  Program:   TiledRayCast
  Module:    BenchmarkReferenceRenderer.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Times the exact CPU reference renderer (vtkTetReferenceRenderer) on datasets, and with
// --bunyk compares it with VTK's vtkUnstructuredGridVolumeRayCastMapper (Bunyk, partial
// pre-integration) rendered in a VTK window (needs X: run under xvfb-run).
//
//   BenchmarkReferenceRenderer [--size N] [--repeat R] [--tf KIND] [--bunyk] <Meshes dir>
//                              [file.vtu ...]
//
// Defaults: 256 x 256, best of 3 renders, the datasets spx_vistrails, bluntfin_tets,
// post_tets6_conforming and comb6teeth_tetgen_270k. The scene: a three-node colour ramp and an
// opacity ramp (0.05 to 0.9) over the scalar range, unit distance = diagonal / 15, the camera
// VTK's ResetCamera() gives (view angle 30), then Azimuth(30), Elevation(20), Zoom(1.3).
// --tf chooses the colour interpolation: rgb (default; linear between nodes, closed form), hsv,
// lab, diverging, or sharpness (RGB with midpoint 0.3 and sharpness 0.5 on every node: Hermite
// curves). Prints one line per dataset (threads = vtkSMPTools threads).
#include "TiledRayCastSharedScenes.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkTetReferenceRenderer.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkWindowToImageFilter.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace
{
// A dataset's scene: its property, and a VTK renderer holding its volume and camera.
struct Scene
{
  vtkSmartPointer<vtkVolumeProperty> Property;
  vtkSmartPointer<vtkRenderer> Renderer;
};

// The scene of TestTetReferenceRendererBunyk (TiledRayCastSharedScenes.h) for `grid`, its colour
// interpolation `tf`, in a VTK renderer (its camera placement; rendered only with --bunyk).
Scene MakeScene(vtkUnstructuredGrid* grid, const std::string& tf)
{
  double range[2], bounds[6];
  grid->GetPointData()->GetScalars()->GetRange(range);
  grid->GetBounds(bounds);
  const double mid = tf == "sharpness" ? 0.3 : 0.5, sharp = tf == "sharpness" ? 0.5 : 0.0;
  vtkSmartPointer<vtkVolumeProperty> property =
    trcscene::MakeBunykProperty(range, trcscene::Diagonal(bounds), mid, sharp);
  vtkColorTransferFunction* color = property->GetRGBTransferFunction(0);
  if (tf == "hsv")
  {
    color->SetColorSpaceToHSV();
  }
  else if (tf == "lab")
  {
    color->SetColorSpaceToLab();
  }
  else if (tf == "diverging")
  {
    color->SetColorSpaceToDiverging();
  }
  vtkSmartPointer<vtkVolume> volume = trcscene::MakeBunykVolume(grid, property);
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->AddVolume(volume);
  renderer->SetBackground(0, 0, 0);
  renderer->ResetCamera(bounds);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->Azimuth(30.0);
  camera->Elevation(20.0);
  camera->OrthogonalizeViewUp();
  camera->Zoom(1.3);
  renderer->ResetCameraClippingRange(bounds);
  return { property, renderer };
}

// Renders `reference` `repeat` times and prints its line: tetrahedra, preparation, first and
// best ray-casting times, tetrahedra per ray (mean over covered pixels, maximum), coverage.
bool TimeReference(vtkTetReferenceRenderer* reference, int repeat, const std::string& file)
{
  double first = 0.0, best = 1e300, prepare = 0.0;
  for (int r = 0; r < repeat; ++r)
  {
    if (!reference->Render())
    {
      fprintf(stderr, "render failed for %s\n", file.c_str());
      return false;
    }
    const double t = reference->GetLastRayCastTime();
    if (r == 0)
    {
      first = t;
      prepare = reference->GetLastPreparationTime();
    }
    best = std::min(best, t);
  }
  vtkDataArray* counts = reference->GetOutput()->GetPointData()->GetArray("NumberOfTets");
  double sum = 0.0, maxCount = 0.0, covered = 0.0;
  for (vtkIdType p = 0; p < counts->GetNumberOfTuples(); ++p)
  {
    const double n = counts->GetComponent(p, 0);
    sum += n;
    maxCount = std::max(maxCount, n);
    covered += n > 0 ? 1.0 : 0.0;
  }
  const double pixels = static_cast<double>(counts->GetNumberOfTuples());
  printf("%-28s %9lld %9.3f %8.3f %8.3f %9.1f %8.0f %5.1f%%", file.c_str(),
    static_cast<long long>(reference->GetNumberOfTetrahedra()), prepare, first, best,
    covered > 0 ? sum / covered : 0.0, maxCount, 100.0 * covered / pixels);
  return true;
}

// VTK's Bunyk ray caster in `renderer` against `reference` (which it leaves sampling pixel
// corners): its time and the differences to the reference sampled at pixel centres and aligned
// as VTK displays the Bunyk image.
void CompareWithBunyk(vtkRenderer* renderer, vtkTetReferenceRenderer* reference, int size)
{
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  window->SetSize(size, size);
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  window->Render();
  timer->StopTimer();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->SetInputBufferTypeToRGB();
  grab->Update();
  const double black[3] = { 0, 0, 0 };
  vtkNew<vtkImageData> centres, aligned;
  vtkTetReferenceRenderer::ConvertToUnsignedChar(reference->GetOutput(), black, centres);
  double raw[3], stats[3];
  vtkTetReferenceRenderer::CompareImages(centres, grab->GetOutput(), raw);
  reference->SetSampleOffset(0.0, 0.0);
  reference->Render();
  vtkTetReferenceRenderer::EmulateRayCastImageDisplay(reference->GetOutput(), black, aligned);
  vtkTetReferenceRenderer::CompareImages(aligned, grab->GetOutput(), stats);
  printf(" | %8.3f %8.3f/%4.0f/%4.0f   %8.3f/%4.0f/%4.0f", timer->GetElapsedTime(), raw[0], raw[1],
    raw[2], stats[0], stats[1], stats[2]);
}
} // namespace

int main(int argc, char* argv[])
{
  int size = 256, repeat = 3;
  bool bunyk = false;
  std::string tf = "rgb";
  std::vector<std::string> args;
  for (int i = 1; i < argc; ++i)
  {
    if (!strcmp(argv[i], "--size") && i + 1 < argc)
    {
      size = std::max(1, atoi(argv[++i]));
    }
    else if (!strcmp(argv[i], "--repeat") && i + 1 < argc)
    {
      repeat = std::max(1, atoi(argv[++i]));
    }
    else if (!strcmp(argv[i], "--tf") && i + 1 < argc)
    {
      tf = argv[++i];
    }
    else if (!strcmp(argv[i], "--bunyk"))
    {
      bunyk = true;
    }
    else
    {
      args.emplace_back(argv[i]);
    }
  }
  if (args.empty())
  {
    fprintf(
      stderr, "usage: %s [--size N] [--repeat R] [--bunyk] <Meshes dir> [file.vtu ...]\n", argv[0]);
    return 1;
  }
  if (bunyk && !getenv("DISPLAY"))
  {
    fprintf(stderr, "--bunyk needs an X display (run under xvfb-run -a)\n");
    return 1;
  }
  const std::string dir = args[0];
  std::vector<std::string> files(args.begin() + 1, args.end());
  if (files.empty())
  {
    files = { "spx_vistrails.vtu", "bluntfin_tets.vtu", "post_tets6_conforming.vtu",
      "comb6teeth_tetgen_270k.vtu" };
  }

  if (tf != "rgb" && tf != "hsv" && tf != "lab" && tf != "diverging" && tf != "sharpness")
  {
    fprintf(stderr, "unknown --tf %s\n", tf.c_str());
    return 1;
  }
  printf("# vtkTetReferenceRenderer, %d x %d, best of %d, %d threads (%s), colour %s\n", size, size,
    repeat, vtkSMPTools::GetEstimatedNumberOfThreads(), vtkSMPTools::GetBackend(), tf.c_str());
  printf("%-28s %9s %9s %8s %8s %9s %8s %6s", "dataset", "tets", "prepare_s", "first_s", "best_s",
    "tets/ray", "max", "cover");
  if (bunyk)
  {
    printf(" | %8s %22s %22s", "bunyk_s", "centres rmse/p99.9/max", "aligned rmse/p99.9/max");
  }
  printf("\n");

  for (const std::string& file : files)
  {
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName((dir + "/" + file).c_str());
    reader->Update();
    vtkUnstructuredGrid* grid = reader->GetOutput();
    if (!grid || grid->GetNumberOfCells() == 0 || !grid->GetPointData()->GetScalars())
    {
      fprintf(stderr, "cannot read %s\n", (dir + "/" + file).c_str());
      return 1;
    }
    const Scene scene = MakeScene(grid, tf);
    vtkNew<vtkTetReferenceRenderer> reference;
    reference->SetInputData(grid);
    reference->SetVolumeProperty(scene.Property);
    reference->SetCamera(scene.Renderer->GetActiveCamera());
    reference->SetImageSize(size, size);
    if (!TimeReference(reference, repeat, file))
    {
      return 1;
    }
    if (bunyk)
    {
      CompareWithBunyk(scene.Renderer, reference, size);
    }
    printf("\n");
    fflush(stdout);
  }
  return 0;
}
