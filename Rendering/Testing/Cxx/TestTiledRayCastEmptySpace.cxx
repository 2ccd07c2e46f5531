/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTiledRayCastEmptySpace.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Empty-space skipping by the transfer function (vtkTiledRayCastVolumeMapper::
// SetEmptySpaceSkipping): tetrahedra whose scalars map to zero opacity are left out and rays
// jump over them to the next face of the visible part. Checked against the exact reference with
// the default bounds, and against the same mapper with skipping off (the same pixels, more
// steps): a 2 %-wide band of bluntfin in both pipelines, in the 2D table mode, with cell
// scalars, the camera inside a cube whose near plane lies in empty space, a transfer function
// that is zero everywhere (nothing drawn, no message), reclassification when the transfer
// function or the scalars change, and no skipping under a blend mode other than compositing.
#include "TiledRayCastTestScene.h"

#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkDoubleArray.h"
#include "vtkPiecewiseFunction.h"
#include "vtkTesting.h"
#include "vtkTiledRayCastStatistics.h"
#include "vtkTimerLog.h"
#include "vtkVolumeMapper.h"

#include <cstdlib>
#include <string>

namespace
{
using trctest::Expect;

// The window's pixels.
vtkSmartPointer<vtkUnsignedCharArray> Pixels(vtkRenderWindow* window)
{
  int* size = window->GetSize();
  auto pixels = vtkSmartPointer<vtkUnsignedCharArray>::New();
  window->GetPixelData(0, 0, size[0] - 1, size[1] - 1, 0, pixels, 0);
  return pixels;
}

int MaximumDifference(vtkUnsignedCharArray* a, vtkUnsignedCharArray* b)
{
  int worst = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i)
  {
    worst = std::max(worst, std::abs(int(a->GetValue(i)) - int(b->GetValue(i))));
  }
  return worst;
}

// Renders with skipping, checks against the reference, then renders with skipping off and
// compares: the same pixels, fewer tets visible and fewer steps with skipping.
bool CheckSkipping(trctest::WatchedVolume& scene, const std::string& label)
{
  vtkTiledRayCastVolumeMapper* mapper = scene.Mapper;
  vtkTiledRayCastStatistics* stats = mapper->GetStatistics();
  mapper->SynchronousStatisticsOn();
  mapper->EmptySpaceSkippingOn();
  vtkNew<vtkTimerLog> timer;
  scene.Window->Render();
  bool ok = trctest::CheckAgainstReference(
    scene.Window, scene.Renderer, scene.Volume, trctest::Bounds(), label.c_str());
  timer->StartTimer();
  scene.Window->Render();
  timer->StopTimer();
  const double skippingTime = timer->GetElapsedTime();
  vtkSmartPointer<vtkUnsignedCharArray> skipped = Pixels(scene.Window);
  const vtkIdType visible = stats->GetNumberOfVisibleTetrahedra();
  const vtkIdType steps = stats->GetNumberOfSteps();
  const vtkIdType rays = stats->GetNumberOfRays();
  const vtkIdType tets = mapper->GetInput()->GetNumberOfCells();

  mapper->EmptySpaceSkippingOff();
  scene.Window->Render();
  timer->StartTimer();
  scene.Window->Render();
  timer->StopTimer();
  vtkSmartPointer<vtkUnsignedCharArray> full = Pixels(scene.Window);
  const int difference = MaximumDifference(skipped, full);
  std::cout << label << ": " << visible << " of " << stats->GetNumberOfVisibleTetrahedra()
            << " tets visible, " << steps << " steps (" << stats->GetNumberOfSteps()
            << " without skipping), " << rays << " rays (" << stats->GetNumberOfRays()
            << "), frame " << 1e3 * skippingTime << " ms (" << 1e3 * timer->GetElapsedTime()
            << " ms without); largest pixel difference " << difference << "/255\n";
  ok = Expect(visible > 0 && visible < tets, label + ": some tets are left out") && ok;
  ok = Expect(stats->GetNumberOfVisibleTetrahedra() >= tets,
         label + ": without skipping every tet is visible") &&
    ok;
  ok = Expect(difference <= 1, label + ": the same image as without skipping") && ok;
  const bool compute = std::string(stats->GetPipeline()) == "Compute";
  ok = Expect(!compute || steps < stats->GetNumberOfSteps(), label + ": fewer steps") && ok;
  ok = Expect(rays <= stats->GetNumberOfRays(), label + ": no more rays") && ok;
  mapper->EmptySpaceSkippingOn();
  return ok;
}

bool TestBand(vtkUnstructuredGrid* grid)
{
  double range[2];
  grid->GetPointData()->GetScalars()->GetRange(range);
  trctest::WatchedVolume scene(
    grid, trcscene::MakeBandProperty(range, 0.3, 0.02, grid->GetLength() / 20), 160);
  scene.Renderer->GetActiveCamera()->Azimuth(30);
  scene.Renderer->GetActiveCamera()->Elevation(20);
  scene.Renderer->ResetCameraClippingRange();
  bool ok = CheckSkipping(scene, "band, compute");
  vtkTiledRayCastStatistics* stats = scene.Mapper->GetStatistics();
  ok = Expect(stats->GetNumberOfLayers() >= 2, "the band's shell has several layers") && ok;

  scene.Mapper->SetPipelineToFragment();
  ok = CheckSkipping(scene, "band, fragment") && ok;
  scene.Mapper->SetPipelineToAutomatic();

  // The 2D table: its own bounds against the reference, but the same pixels with or without.
  scene.Mapper->SetIntegrationMode(vtkTiledRayCastVolumeMapper::PRE_INTEGRATION_2D);
  scene.Window->Render();
  vtkSmartPointer<vtkUnsignedCharArray> table = Pixels(scene.Window);
  scene.Mapper->EmptySpaceSkippingOff();
  scene.Window->Render();
  ok = Expect(MaximumDifference(table, Pixels(scene.Window)) <= 1,
         "2D table: the same image with and without skipping") &&
    ok;
  scene.Mapper->EmptySpaceSkippingOn();
  scene.Mapper->SetIntegrationMode(vtkTiledRayCastVolumeMapper::PARTIAL_PRE_INTEGRATION);

  // A new transfer function reclassifies: the ramp of the scenes has no empty space.
  vtkSmartPointer<vtkVolumeProperty> band = scene.Volume->GetProperty();
  scene.Volume->SetProperty(trctest::MakeProperty(range[0], range[1], grid->GetLength() / 20));
  scene.Window->Render();
  ok = Expect(stats->GetNumberOfVisibleTetrahedra() == grid->GetNumberOfCells(),
         "the ramp leaves every tet visible") &&
    ok;
  ok = Expect(stats->GetNumberOfEntryFaces() < stats->GetNumberOfVisibleTetrahedra(),
         "the ramp's rays enter by the mesh's boundary") &&
    ok;
  // Back to the band, then moved by editing its function: reclassified each time.
  scene.Volume->SetProperty(band);
  scene.Window->Render();
  const vtkIdType bandVisible = stats->GetNumberOfVisibleTetrahedra();
  vtkPiecewiseFunction* opacity = band->GetScalarOpacity();
  opacity->RemoveAllPoints();
  const double w = range[1] - range[0];
  opacity->AddPoint(range[0] + 0.2 * w, 0.0);
  opacity->AddPoint(range[0] + 0.25 * w, 0.8);
  opacity->AddPoint(range[0] + 0.3 * w, 0.0);
  scene.Window->Render();
  ok = Expect(stats->GetNumberOfVisibleTetrahedra() != bandVisible, "an edited function") && ok;
  ok = trctest::CheckAgainstReference(
         scene.Window, scene.Renderer, scene.Volume, trctest::Bounds(), "edited band") &&
    ok;

  // New scalars reclassify: the same band over the negated field shows the other shell.
  vtkNew<vtkUnstructuredGrid> negated;
  negated->DeepCopy(grid);
  vtkDataArray* scalars = negated->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < scalars->GetNumberOfTuples(); ++i)
  {
    scalars->SetTuple1(i, range[0] + range[1] - scalars->GetTuple1(i));
  }
  scene.Mapper->SetInputData(negated);
  scene.Window->Render();
  ok = trctest::CheckAgainstReference(
         scene.Window, scene.Renderer, scene.Volume, trctest::Bounds(), "negated scalars") &&
    ok;

  // Under a blend mode other than compositing, zero opacity still counts: nothing is skipped.
  scene.Mapper->SetInputData(grid);
  scene.Mapper->SetBlendModeToMaximumIntensity();
  scene.Window->Render();
  ok = Expect(stats->GetNumberOfVisibleTetrahedra() == grid->GetNumberOfCells(),
         "maximum intensity skips nothing") &&
    ok;
  ok = Expect(scene.Warnings->Count == 0, "no warning") && ok;
  return ok;
}

bool TestCellScalars(vtkUnstructuredGrid* grid)
{
  vtkSmartPointer<vtkUnstructuredGrid> cells = trctest::WithCellScalars(grid, false);
  double range[2];
  cells->GetCellData()->GetScalars()->GetRange(range);
  trctest::WatchedVolume scene(
    cells, trcscene::MakeBandProperty(range, 0.5, 0.1, grid->GetLength() / 20), 160);
  scene.Renderer->GetActiveCamera()->Azimuth(-40);
  scene.Renderer->ResetCameraClippingRange();
  return CheckSkipping(scene, "cell scalars");
}

// The camera inside a cube, its near plane in empty space: rays start at the faces of the
// visible part behind it (no near-plane entry in an invisible tet).
bool TestInside(vtkUnstructuredGrid* grid)
{
  double range[2], centre[3];
  grid->GetPointData()->GetScalars()->GetRange(range);
  grid->GetCenter(centre);
  trctest::WatchedVolume scene(
    grid, trcscene::MakeBandProperty(range, 0.3, 0.05, grid->GetLength() / 10), 160);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->SetFocalPoint(centre[0] + 1, centre[1] + 0.3, centre[2] + 0.2);
  camera->SetPosition(centre);
  camera->SetViewAngle(60);
  scene.Renderer->ResetCameraClippingRange();
  bool ok = CheckSkipping(scene, "inside, compute");
  scene.Mapper->SetPipelineToFragment();
  ok = CheckSkipping(scene, "inside, fragment") && ok;
  return ok;
}

// Zero opacity everywhere: nothing visible, nothing drawn, nothing said.
bool TestTransparent(vtkUnstructuredGrid* grid)
{
  double range[2];
  grid->GetPointData()->GetScalars()->GetRange(range);
  vtkSmartPointer<vtkVolumeProperty> property = trcscene::MakeBandProperty(range, 0.5, 0.1, 1.0);
  property->GetScalarOpacity()->RemoveAllPoints();
  property->GetScalarOpacity()->AddPoint(range[0], 0.0);
  property->GetScalarOpacity()->AddPoint(range[1], 0.0);
  trctest::WatchedVolume scene(grid, property, 64);
  trctest::MessageCounter* errors = scene.CountErrors();
  scene.Mapper->SynchronousStatisticsOn();
  scene.Renderer->SetBackground(0.2, 0.3, 0.4);
  scene.Window->Render();
  vtkTiledRayCastStatistics* stats = scene.Mapper->GetStatistics();
  bool ok = Expect(stats->GetNumberOfVisibleTetrahedra() == 0, "no tet visible");
  ok = Expect(stats->GetNumberOfEntryFaces() == 0 && stats->GetNumberOfRays() == 0,
         "no face drawn, no ray") &&
    ok;
  vtkSmartPointer<vtkUnsignedCharArray> pixels = Pixels(scene.Window);
  scene.Volume->VisibilityOff();
  scene.Window->Render();
  ok =
    Expect(MaximumDifference(pixels, Pixels(scene.Window)) == 0, "the background is untouched") &&
    ok;
  ok = Expect(scene.Warnings->Count == 0 && errors->Count == 0, "no message") && ok;
  return ok;
}
}

int TestTiledRayCastEmptySpace(int argc, char* argv[])
{
  vtkSmartPointer<vtkUnstructuredGrid> fin = trctest::ReadMesh(argc, argv, "bluntfin_tets.vtu");
  vtkSmartPointer<vtkUnstructuredGrid> cube = trctest::ReadMesh(argc, argv, "cube_sfepy_200k.vtu");
  if (!fin || !cube)
  {
    return EXIT_FAILURE;
  }
  if (!trctest::RenderingSupported())
  {
    return VTK_SKIP_RETURN_CODE;
  }
  bool ok = TestBand(fin);
  ok = TestCellScalars(fin) && ok;
  ok = TestInside(cube) && ok;
  ok = TestTransparent(fin) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
