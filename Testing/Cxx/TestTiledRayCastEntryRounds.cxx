/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTiledRayCastEntryRounds.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The compute pipeline's entry list without a CPU wait: Render() does not read back how many
// entries a view asked for. The list is sized from earlier frames; a view that asks for more
// is listed again on the GPU in rounds (the pixels that did not fit), and a frame that even
// three rounds cannot list is either drawn again at once (verified frames: the first of a mesh
// or image size, or with SynchronousStatistics) or drawn with layers missing and a warning,
// the list grown for the next frame. Each case checked against the exact reference:
//   1. the comb from the front, far (two layers), then across its six teeth, close: more
//      entries than the list holds, listed in two or three rounds, exact, no warning;
//   2. a stack of 16 thin slabs seen edge-on (one layer), then face-on filling the window
//      (16 layers at every pixel: more than three rounds hold), with SynchronousStatistics
//      off: a warning, then exact frames;
//   3. the same with SynchronousStatistics on: the frame itself exact, no warning.
#include "TiledRayCastTestScene.h"

#include "vtkAppendFilter.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkTesting.h"
#include "vtkTiledRayCastStatistics.h"

namespace
{
using trctest::Expect;

// The rounds, entries and incomplete rays of the frame the counts describe.
void Print(const char* label, vtkTiledRayCastStatistics* stats)
{
  std::cout << label << ": " << stats->GetNumberOfEntries() << " entries, "
            << stats->GetNumberOfEntryRounds() << " rounds, "
            << stats->GetNumberOfIncompleteRays() << " incomplete rays\n";
}

bool CombRounds(int argc, char* argv[])
{
  vtkSmartPointer<vtkUnstructuredGrid> grid = trctest::ReadMesh(argc, argv, "comb6teeth_tetgen_270k.vtu");
  if (!grid)
  {
    return false;
  }
  trctest::WatchedVolume scene(grid, trctest::MakePropertyFor(grid, 0.2), 200);
  scene.Mapper->SetPipelineToCompute();
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->Elevation(10);
  camera->OrthogonalizeViewUp();
  camera->Zoom(0.3);
  scene.Renderer->ResetCameraClippingRange();
  scene.Window->Render(); // verified: the list is sized from this view
  Print("comb, front, far", scene.Mapper->GetStatistics());

  camera->Azimuth(90);
  camera->Zoom(16);
  scene.Renderer->ResetCameraClippingRange();
  // This frame is not verified; CheckAgainstReference renders it (after a frame without the
  // volume) and compares it.
  bool ok = trctest::CheckAgainstReference(
    scene.Window, scene.Renderer, scene.Volume, trctest::Bounds(), "comb across, close");
  // The next frame reads that frame's counts without waiting for its own.
  scene.Window->Render();
  vtkTiledRayCastStatistics* stats = scene.Mapper->GetStatistics();
  Print("comb across, close", stats);
  ok = Expect(stats->GetNumberOfEntryRounds() >= 2, "the close view was listed in rounds") && ok;
  ok = Expect(stats->GetNumberOfIncompleteRays() == 0, "no ray incomplete") && ok;
  ok = Expect(scene.Warnings->Count == 0, "no warning") && ok;
  return ok;
}

vtkSmartPointer<vtkUnstructuredGrid> SlabStack(int slabs)
{
  vtkNew<vtkAppendFilter> append;
  for (int i = 0; i < slabs; ++i)
  {
    vtkNew<vtkImageData> slab;
    slab->SetDimensions(2, 2, 2);
    slab->SetSpacing(1.0, 1.0, 0.03);
    slab->SetOrigin(0.0, 0.0, 0.1 * i);
    vtkNew<vtkFloatArray> scalars;
    scalars->SetName("scalar");
    for (vtkIdType p = 0; p < 8; ++p)
    {
      const double* x = slab->GetPoint(p);
      scalars->InsertNextValue(static_cast<float>(x[0] + x[1] + x[2]));
    }
    slab->GetPointData()->SetScalars(scalars);
    vtkNew<vtkDataSetTriangleFilter> tets;
    tets->SetInputData(slab);
    append->AddInputConnection(tets->GetOutputPort());
  }
  append->Update();
  vtkSmartPointer<vtkUnstructuredGrid> grid = append->GetOutput();
  return grid;
}

bool SlabOverflow(bool synchronous)
{
  const int slabs = 16;
  vtkSmartPointer<vtkUnstructuredGrid> grid = SlabStack(slabs);
  trctest::WatchedVolume scene(grid, trctest::MakePropertyFor(grid, 0.02), 200);
  scene.Mapper->SetPipelineToCompute();
  scene.Mapper->SetSynchronousStatistics(synchronous);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  // Edge-on: along x, every ray enters the stack once.
  camera->SetFocalPoint(0.5, 0.5, 0.8);
  camera->SetPosition(-5.0, 0.5, 0.8);
  camera->SetViewUp(0, 0, 1);
  scene.Renderer->ResetCameraClippingRange();
  scene.Window->Render();
  Print("slabs, edge-on", scene.Mapper->GetStatistics());

  // Face-on, close: every pixel crosses all 16 slabs.
  camera->SetPosition(0.5, 0.5, -1.0);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(20);
  scene.Renderer->ResetCameraClippingRange();
  const char* label = synchronous ? "slabs face-on, verified" : "slabs face-on, next frames";
  bool ok = true;
  if (synchronous)
  {
    ok = trctest::CheckAgainstReference(
      scene.Window, scene.Renderer, scene.Volume, trctest::Bounds(), label);
    Print(label, scene.Mapper->GetStatistics());
    ok = Expect(scene.Warnings->Count == 0, "no warning: the frame was drawn again") && ok;
    ok = Expect(scene.Mapper->GetStatistics()->GetNumberOfIncompleteRays() == 0,
           "no ray incomplete") &&
      ok;
    return ok;
  }
  // Not verified: this frame misses layers; within the next two frames (the counts of a frame
  // arrive by the second after it) the mapper says so once and grows the list.
  scene.Window->Render();
  for (int frame = 0; frame < 2 && scene.Warnings->Count == 0; ++frame)
  {
    scene.Window->Render();
  }
  std::cout << "warning: " << scene.Warnings->Text << "\n";
  ok = Expect(scene.Warnings->Count == 1 &&
      scene.Warnings->Text.find("missed boundary layers") != std::string::npos,
    "one warning for the frame that missed layers");
  ok = trctest::CheckAgainstReference(
         scene.Window, scene.Renderer, scene.Volume, trctest::Bounds(), label) &&
    ok;
  scene.Window->Render();
  vtkTiledRayCastStatistics* stats = scene.Mapper->GetStatistics();
  Print(label, stats);
  ok = Expect(stats->GetNumberOfEntries() >= 200 * 200 * slabs * 9 / 10, "every slab listed") &&
    ok;
  ok = Expect(stats->GetNumberOfEntryRounds() == 1 && stats->GetNumberOfIncompleteRays() == 0,
         "the grown list holds the view in one round") &&
    ok;
  ok = Expect(scene.Warnings->Count == 1, "no further warning") && ok;
  return ok;
}
}

int TestTiledRayCastEntryRounds(int argc, char* argv[])
{
  {
    // Skip where the compute pipeline cannot run (OpenGL < 4.3).
    vtkNew<vtkRenderWindow> window;
    window->SetSize(8, 8);
    window->Render();
    vtkNew<vtkTiledRayCastVolumeMapper> mapper;
    mapper->SetPipelineToCompute();
    vtkNew<vtkVolumeProperty> property;
    if (!mapper->IsRenderSupported(window, property))
    {
      return VTK_SKIP_RETURN_CODE;
    }
  }
  bool ok = CombRounds(argc, argv);
  ok = SlabOverflow(false) && ok;
  ok = SlabOverflow(true) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
