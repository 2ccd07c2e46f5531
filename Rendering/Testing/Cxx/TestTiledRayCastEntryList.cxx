/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTiledRayCastEntryList.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The compute pipeline's entry list without a CPU wait: Render() does not read back how many
// entries a view asked for. The list is sized from earlier frames; a frame it does not hold is
// either drawn again at once (verified frames: the first of a mesh or image size, a camera
// jump, or with SynchronousStatistics) or drawn with layers missing and a warning, the list
// grown for the next frame. Each case checked against the exact reference:
//   1. the comb from the front, far (two layers), then across its six teeth, close: a camera
//      jump, so a verified frame: exact, no warning; then a camera that moves in small steps
//      from the front to across the teeth, coming closer: no ray incomplete, exact, and every
//      frame's statistics hold the latest counts that arrived (none zero);
//   2. a stack of 16 thin slabs seen nearly edge-on, then turned by 25 degrees (several slabs
//      per ray), with SynchronousStatistics off: one warning exactly when rays were
//      incomplete, and exact frames after;
//   3. the same with SynchronousStatistics on: the frame itself exact, no warning.
#include "TiledRayCastTestScene.h"

#include "vtkAppendFilter.h"
#include "vtkMath.h"
#include "vtkTesting.h"
#include "vtkTiledRayCastStatistics.h"

#include <cmath>

namespace
{
using trctest::Expect;

// The entries and incomplete rays of the frame the counts describe.
void Print(const char* label, vtkTiledRayCastStatistics* stats)
{
  std::cout << label << ": " << stats->GetNumberOfEntries() << " entries, "
            << stats->GetNumberOfIncompleteRays() << " incomplete rays\n";
}

bool CombRounds(int argc, char* argv[])
{
  vtkSmartPointer<vtkUnstructuredGrid> grid =
    trctest::ReadMesh(argc, argv, "comb6teeth_tetgen_270k.vtu");
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

  // A camera jump: across the teeth, close, twice the entries the list holds. The frame is
  // verified (drawn again since the list did not hold it): exact, no warning.
  camera->Azimuth(90);
  camera->Zoom(16);
  scene.Renderer->ResetCameraClippingRange();
  bool ok = trctest::CheckAgainstReference(
    scene.Window, scene.Renderer, scene.Volume, trctest::Bounds(), "comb across, close");
  Print("comb across, close", scene.Mapper->GetStatistics());

  // A camera that moves: back to the front and across again in 10-degree steps, coming closer,
  // SynchronousStatistics off. The list follows the counts of earlier frames with room to
  // spare: the last frame is exact and nothing was incomplete.
  camera->Azimuth(-90);
  camera->Zoom(1.0 / 3.0);
  scene.Renderer->ResetCameraClippingRange();
  scene.Window->Render();
  vtkIdType incomplete = 0;
  int framesWithoutCounts = 0;
  for (int step = 0; step < 9; ++step)
  {
    camera->Azimuth(10);
    camera->Zoom(1.1);
    scene.Renderer->ResetCameraClippingRange();
    scene.Window->Render();
    incomplete += scene.Mapper->GetStatistics()->GetNumberOfIncompleteRays();
    // The latest counts that arrived, never zeros: the first of these frames follows a verified
    // one, which read its own counts, so none is pending when it begins.
    framesWithoutCounts += scene.Mapper->GetStatistics()->GetNumberOfRays() > 0 ? 0 : 1;
  }
  ok = Expect(framesWithoutCounts == 0, "every frame's statistics hold counts") && ok;
  ok = trctest::CheckAgainstReference(
         scene.Window, scene.Renderer, scene.Volume, trctest::Bounds(), "comb, camera moved") &&
    ok;
  std::cout << "comb, camera moved: " << incomplete << " incomplete rays\n";
  ok = Expect(incomplete == 0 && scene.Warnings->Count == 0, "no ray incomplete, no warning") && ok;
  return ok;
}

vtkSmartPointer<vtkUnstructuredGrid> SlabStack(int slabs)
{
  vtkNew<vtkAppendFilter> append;
  for (int i = 0; i < slabs; ++i)
  {
    append->AddInputData(trctest::TetrahedralBox({ 1.0, 1.0, 0.03 }, { 0.0, 0.0, 0.1 * i },
      [](const double* x) { return x[0] + x[1] + x[2]; }));
  }
  append->Update();
  vtkSmartPointer<vtkUnstructuredGrid> grid = append->GetOutput();
  return grid;
}

// A camera turning by 25 degrees (no jump) from nearly edge-on (one or two slabs per ray) to
// where rays cross several slabs: three times the entries, more than the list holds.
// Never silent: a frame with incomplete rays is followed by one warning, and the next frames
// are exact. With SynchronousStatistics the frame itself is exact.
bool SlabOverflow(bool synchronous)
{
  const int slabs = 16;
  vtkSmartPointer<vtkUnstructuredGrid> grid = SlabStack(slabs);
  trctest::WatchedVolume scene(grid, trctest::MakePropertyFor(grid, 0.02), 200);
  scene.Mapper->SetPipelineToCompute();
  scene.Mapper->SetSynchronousStatistics(synchronous);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  auto view = [&](double degreesFromNormal)
  {
    const double a = vtkMath::RadiansFromDegrees(degreesFromNormal);
    camera->SetFocalPoint(0.5, 0.5, 0.8);
    camera->SetPosition(0.5 - 3.0 * std::sin(a), 0.5, 0.8 - 3.0 * std::cos(a));
    camera->SetViewUp(0, 1, 0);
    scene.Renderer->ResetCameraClippingRange();
  };
  view(85);
  scene.Window->Render();
  Print("slabs, nearly edge-on", scene.Mapper->GetStatistics());

  view(60);
  const char* label = synchronous ? "slabs turned, verified" : "slabs turned";
  bool ok = true;
  if (synchronous)
  {
    ok = trctest::CheckAgainstReference(
      scene.Window, scene.Renderer, scene.Volume, trctest::Bounds(), label);
    Print(label, scene.Mapper->GetStatistics());
    ok = Expect(scene.Warnings->Count == 0, "no warning") && ok;
    ok = Expect(
           scene.Mapper->GetStatistics()->GetNumberOfIncompleteRays() == 0, "no ray incomplete") &&
      ok;
    return ok;
  }
  // The turned frame, then two more: the counts of a frame arrive by the second after it.
  vtkIdType incomplete = 0;
  for (int frame = 0; frame < 3; ++frame)
  {
    scene.Window->Render();
    Print(label, scene.Mapper->GetStatistics());
    incomplete += scene.Mapper->GetStatistics()->GetNumberOfIncompleteRays();
  }
  std::cout << "warnings: " << scene.Warnings->Count << " " << scene.Warnings->Text << "\n";
  ok = Expect(scene.Warnings->Count == (incomplete > 0 ? 1 : 0) &&
      (incomplete == 0 || scene.Warnings->Text.find("missed boundary layers") != std::string::npos),
    "one warning exactly when rays were incomplete");
  ok = trctest::CheckAgainstReference(
         scene.Window, scene.Renderer, scene.Volume, trctest::Bounds(), label) &&
    ok;
  scene.Window->Render();
  vtkTiledRayCastStatistics* stats = scene.Mapper->GetStatistics();
  Print(label, stats);
  ok = Expect(stats->GetNumberOfIncompleteRays() == 0, "the grown list holds the view") && ok;
  return ok;
}
}

int TestTiledRayCastEntryList(int argc, char* argv[])
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
