/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTiledRayCastAutomatic.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The automatic integration mode (vtkTiledRayCastVolumeMapper::AUTOMATIC_INTEGRATION with
// MaximumError): the cheapest integration whose predicted error fits the budget. Bluntfin under
// the scenes' smooth ramp takes the 2D table; five huge tets, where the 2D table is 11/255 off,
// and a 2 %-wide opacity band, where both tables are 4/255 off at grazing rays, take partial
// pre-integration; a budget of 255 takes the 2D table anywhere; a new transfer function is
// decided again; a blend mode other than compositing uses partial pre-integration's nodes as
// always. Without SynchronousStatistics a new transfer function is drawn at once with partial
// pre-integration while the choice is made on a worker thread, and with its table once made;
// edits in quick succession abandon the choices they overtake, and a key that changes in
// consecutive frames is not chosen for until a frame keeps it. Every image is checked against
// the exact reference with the default bounds.
#include "TiledRayCastTestScene.h"

#include "vtkPiecewiseFunction.h"
#include "vtkTesting.h"
#include "vtkTiledRayCastStatistics.h"
#include "vtkTimerLog.h"
#include "vtksys/SystemTools.hxx"

#include <string>

namespace
{
using trctest::Expect;
using M = vtkTiledRayCastVolumeMapper;

bool Check(trctest::WatchedVolume& scene, int expectedMode, const std::string& label)
{
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  scene.Window->Render();
  timer->StopTimer();
  vtkTiledRayCastStatistics* stats = scene.Mapper->GetStatistics();
  std::cout << label << ": " << M::GetIntegrationModeAsString(stats->GetIntegrationMode())
            << ", predicted error " << stats->GetPredictedError() << "/255, frame with the choice "
            << timer->GetElapsedTime() << " s\n";
  bool ok = Expect(stats->GetIntegrationMode() == expectedMode,
    label + ": " + M::GetIntegrationModeAsString(expectedMode) + " is taken");
  ok = Expect(stats->GetPredictedError() <= scene.Mapper->GetMaximumError(),
         label + ": the prediction fits the budget") &&
    ok;
  return trctest::CheckAgainstReference(
           scene.Window, scene.Renderer, scene.Volume, trctest::Bounds(), label.c_str()) &&
    ok;
}

void View(trctest::WatchedVolume& scene)
{
  scene.Renderer->GetActiveCamera()->Azimuth(30);
  scene.Renderer->GetActiveCamera()->Elevation(20);
  scene.Renderer->ResetCameraClippingRange();
}
}

int TestTiledRayCastAutomatic(int argc, char* argv[])
{
  vtkSmartPointer<vtkUnstructuredGrid> fin = trctest::ReadMesh(argc, argv, "bluntfin_tets.vtu");
  vtkSmartPointer<vtkUnstructuredGrid> box = trctest::ReadMesh(argc, argv, "box5_tets.vtu");
  if (!fin || !box)
  {
    return EXIT_FAILURE;
  }
  if (!trctest::RenderingSupported())
  {
    return VTK_SKIP_RETURN_CODE;
  }
  bool ok = true;
  {
    trctest::WatchedVolume scene(fin, trctest::MakePropertyFor(fin, 0.05), 160);
    scene.Mapper->SetIntegrationModeToAutomatic();
    scene.Mapper->SynchronousStatisticsOn();
    View(scene);
    ok = Check(scene, M::PRE_INTEGRATION_2D, "bluntfin, ramp") && ok;
    // A narrow band: both tables are refused.
    double range[2];
    fin->GetPointData()->GetScalars()->GetRange(range);
    scene.Volume->SetProperty(
      trcscene::MakeBandProperty(range, 0.49, 0.02, 0.05 * fin->GetLength()));
    ok = Check(scene, M::PARTIAL_PRE_INTEGRATION, "bluntfin, band") && ok;
    // Any error allowed: the cheapest table.
    scene.Mapper->SetMaximumError(255);
    scene.Window->Render();
    ok = Expect(scene.Mapper->GetStatistics()->GetIntegrationMode() == M::PRE_INTEGRATION_2D,
           "a budget of 255 takes the 2D table") &&
      ok;
    scene.Mapper->SetMaximumError(1);
    // Blend modes evaluate partial pre-integration's nodes, automatic or not.
    scene.Mapper->SetBlendModeToMaximumIntensity();
    scene.Window->Render();
    ok = Expect(scene.Mapper->GetStatistics()->GetIntegrationMode() == M::PARTIAL_PRE_INTEGRATION,
           "maximum intensity: partial pre-integration's nodes") &&
      ok;
    ok = Expect(scene.Warnings->Count == 0, "no warning") && ok;
  }
  {
    // The default mode is the automatic one; its choice runs on a worker thread.
    trctest::WatchedVolume scene(fin, trctest::MakePropertyFor(fin, 0.05), 160);
    View(scene);
    scene.Window->Render(); // the first choice is waited for
    vtkTiledRayCastStatistics* stats = scene.Mapper->GetStatistics();
    ok = Expect(stats->GetIntegrationMode() == M::PRE_INTEGRATION_2D,
           "default mode: the first frame waits for the choice (2D table)") &&
      ok;
    // Edits in quick succession: each frame draws at once, with partial pre-integration unless
    // the choice of its edit was already made (a worker thread on a loaded machine can finish
    // before the frame asks for it).
    double range[2];
    fin->GetPointData()->GetScalars()->GetRange(range);
    vtkPiecewiseFunction* opacity = scene.Volume->GetProperty()->GetScalarOpacity();
    for (int edit = 0; edit < 4; ++edit)
    {
      opacity->AddPoint(range[0] + (0.2 + 0.1 * edit) * (range[1] - range[0]), 0.1 + 0.05 * edit);
      scene.Window->Render();
      std::cout << "edit " << edit << ": "
                << M::GetIntegrationModeAsString(stats->GetIntegrationMode()) << "\n";
    }
    ok = trctest::CheckAgainstReference(
           scene.Window, scene.Renderer, scene.Volume, trctest::Bounds(), "after the edits") &&
      ok;
    // The last edit's choice arrives in a later frame.
    vtkNew<vtkTimerLog> timer;
    timer->StartTimer();
    while (stats->GetIntegrationMode() == M::PARTIAL_PRE_INTEGRATION)
    {
      timer->StopTimer();
      if (timer->GetElapsedTime() > 60)
      {
        break;
      }
      vtksys::SystemTools::Delay(20);
      scene.Window->Render();
    }
    timer->StopTimer();
    std::cout << "choice waited for " << timer->GetElapsedTime() << " s after the checks\n";
    ok = Expect(
           stats->GetIntegrationMode() == M::PRE_INTEGRATION_2D, "the choice made: the 2D table") &&
      ok;
    ok = Expect(stats->GetPredictedError() > 0 &&
             stats->GetPredictedError() <= scene.Mapper->GetMaximumError(),
           "the choice made: its prediction fits the budget") &&
      ok;
    ok = trctest::CheckAgainstReference(
           scene.Window, scene.Renderer, scene.Volume, trctest::Bounds(), "choice made") &&
      ok;
    ok = Expect(scene.Warnings->Count == 0, "asynchronous choice: no warning") && ok;
  }
  {
    // A key that changes in consecutive frames (an edit every frame, or points that move) gets
    // no choice until a frame keeps it, even where each frame waits for its choice: each would
    // be abandoned by the next frame's, its table's build taking the cores from the frames.
    trctest::WatchedVolume scene(fin, trctest::MakePropertyFor(fin, 0.05), 160);
    scene.Mapper->SetIntegrationModeToAutomatic();
    scene.Mapper->SynchronousStatisticsOn();
    View(scene);
    scene.Window->Render();
    scene.Window->Render();
    double range[2];
    fin->GetPointData()->GetScalars()->GetRange(range);
    vtkPiecewiseFunction* opacity = scene.Volume->GetProperty()->GetScalarOpacity();
    vtkTiledRayCastStatistics* stats = scene.Mapper->GetStatistics();
    const int expected[3] = { M::PRE_INTEGRATION_2D, M::PARTIAL_PRE_INTEGRATION,
      M::PARTIAL_PRE_INTEGRATION };
    for (int edit = 0; edit < 3; ++edit)
    {
      opacity->AddPoint(range[0] + (0.3 + 0.1 * edit) * (range[1] - range[0]), 0.1 + 0.05 * edit);
      scene.Window->Render();
      ok = Expect(stats->GetIntegrationMode() == expected[edit],
             "edit " + std::to_string(edit) +
               " of consecutive ones: " + M::GetIntegrationModeAsString(expected[edit])) &&
        ok;
    }
    ok = Check(scene, M::PRE_INTEGRATION_2D, "a frame that keeps its key: the choice") && ok;
  }
  {
    trctest::WatchedVolume scene(box, trctest::MakePropertyFor(box, 0.05), 160);
    scene.Mapper->SetIntegrationModeToAutomatic();
    scene.Mapper->SynchronousStatisticsOn();
    View(scene);
    ok = Check(scene, M::PARTIAL_PRE_INTEGRATION, "five huge tets, ramp") && ok;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
