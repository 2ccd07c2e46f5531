/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTiledRayCastInteraction.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Interaction (vtkTiledRayCastVolumeMapper::SetImageSampleDistance and
// AutoAdjustSampleDistances, as in vtkUnstructuredGridVolumeRayCastMapper). A fixed distance of
// 2.5 casts 80 x 80 rays into a 200 x 200 window: checked, in both pipelines and over opaque
// geometry, against the exact reference rendered at 80 x 80 and spread over the window with the
// same bilinear rule (default bounds). With the distance adjusted, a desired update rate the
// frame cannot meet makes the next frames coarser, within the bounds, and the still rate brings
// back one ray per pixel, checked against the full reference.
#include "TiledRayCastTestScene.h"

#include "vtkTesting.h"
#include "vtkTiledRayCastStatistics.h"

#include <cmath>
#include <string>

namespace
{
using trctest::Expect;

// The reference at the mapper's ray image size, spread over the window as the compositing pass
// does (bilinear between ray centres, clamped at the image's edges) and blended over what lies
// behind the volume. Returns false when a bound is exceeded.
bool CheckAgainstCoarseReference(trctest::WatchedVolume& scene, const std::string& label)
{
  vtkTiledRayCastVolumeMapper* mapper = scene.Mapper;
  int* size = scene.Window->GetSize();
  const int w = size[0], h = size[1];
  scene.Window->Render();
  const int* rays = mapper->GetStatistics()->GetImageSize();
  const int rw = rays[0], rh = rays[1];

  scene.Volume->VisibilityOff();
  scene.Window->Render();
  vtkNew<vtkUnsignedCharArray> behind;
  scene.Window->GetPixelData(0, 0, w - 1, h - 1, 0, behind, 0);
  vtkNew<vtkFloatArray> depth;
  scene.Window->GetZbufferData(0, 0, w - 1, h - 1, depth);
  scene.Volume->VisibilityOn();
  scene.Window->Render();
  vtkNew<vtkUnsignedCharArray> pixels;
  scene.Window->GetPixelData(0, 0, w - 1, h - 1, 0, pixels, 0);

  // The opaque depth of each ray: the pixel its centre lies in, as the mapper's depth blit.
  vtkNew<vtkFloatArray> rayDepth;
  rayDepth->SetNumberOfTuples(static_cast<vtkIdType>(rw) * rh);
  for (int y = 0; y < rh; ++y)
  {
    for (int x = 0; x < rw; ++x)
    {
      const int px = std::min(w - 1, static_cast<int>((x + 0.5) * w / rw));
      const int py = std::min(h - 1, static_cast<int>((y + 0.5) * h / rh));
      rayDepth->SetValue(y * rw + x, depth->GetValue(py * w + px));
    }
  }
  vtkNew<vtkTetReferenceRenderer> reference;
  reference->SetInputData(mapper->GetInput());
  reference->SetVolumeProperty(scene.Volume->GetProperty());
  reference->SetCamera(scene.Renderer->GetActiveCamera());
  reference->SetImageSize(rw, rh);
  reference->SetVolume(scene.Volume);
  reference->SetOpaqueDepth(rayDepth);
  if (!reference->Render())
  {
    return Expect(false, label + ": the reference renders");
  }
  vtkDataArray* rgba = reference->GetOutput()->GetPointData()->GetArray("RGBA");
  auto ray = [&](int x, int y, int c)
  {
    x = std::min(std::max(x, 0), rw - 1);
    y = std::min(std::max(y, 0), rh - 1);
    return rgba->GetComponent(static_cast<vtkIdType>(y) * rw + x, c);
  };
  double sum = 0, worst = 0;
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const double ax = (x + 0.5) * rw / w - 0.5, ay = (y + 0.5) * rh / h - 0.5;
      const int cx = static_cast<int>(std::floor(ax)), cy = static_cast<int>(std::floor(ay));
      const double fx = ax - cx, fy = ay - cy;
      double value[4];
      for (int c = 0; c < 4; ++c)
      {
        const double below = (1 - fx) * ray(cx, cy, c) + fx * ray(cx + 1, cy, c);
        const double above = (1 - fx) * ray(cx, cy + 1, c) + fx * ray(cx + 1, cy + 1, c);
        value[c] = (1 - fy) * below + fy * above;
      }
      for (int c = 0; c < 3; ++c)
      {
        const vtkIdType i = 3 * (static_cast<vtkIdType>(y) * w + x) + c;
        const double expected = std::lround(
          255.0 * std::min(1.0, value[c] + (1.0 - value[3]) * behind->GetValue(i) / 255.0));
        const double difference = std::abs(expected - pixels->GetValue(i));
        sum += difference * difference;
        worst = std::max(worst, difference);
      }
    }
  }
  const double rmse = std::sqrt(sum / (3.0 * w * h));
  std::cout << label << ": " << rw << "x" << rh << " rays for " << w << "x" << h
            << " pixels, vs the reference at that size spread the same way (1/255): RMSE " << rmse
            << ", max " << worst << "\n";
  const trctest::Bounds bounds;
  return Expect(rmse <= bounds.RMSE && worst <= bounds.Max, label + ": within the default bounds");
}

bool TestFixedDistance(vtkUnstructuredGrid* grid, int pipeline, bool geometry)
{
  double range[2];
  grid->GetPointData()->GetScalars()->GetRange(range);
  trctest::WatchedVolume scene(
    grid, trctest::MakeProperty(range[0], range[1], grid->GetLength() / 10), 200);
  scene.Renderer->SetBackground(0.1, 0.1, 0.15);
  scene.Mapper->SetPipeline(pipeline);
  scene.Mapper->AutoAdjustSampleDistancesOff();
  scene.Mapper->SetImageSampleDistance(2.5f);
  if (geometry)
  {
    // An opaque ball inside the fin: rays stop at its depth.
    double centre[3];
    grid->GetCenter(centre);
    scene.Renderer->AddActor(trctest::MakeBall(centre, 0.15 * grid->GetLength(), 32));
  }
  scene.Renderer->GetActiveCamera()->Azimuth(40);
  scene.Renderer->GetActiveCamera()->Elevation(15);
  scene.Renderer->ResetCameraClippingRange();
  const std::string label =
    std::string(
      pipeline == vtkTiledRayCastVolumeMapper::COMPUTE_PIPELINE ? "compute" : "fragment") +
    (geometry ? ", opaque ball" : "");
  bool ok = CheckAgainstCoarseReference(scene, label);
  vtkTiledRayCastStatistics* stats = scene.Mapper->GetStatistics();
  ok = Expect(stats->GetImageSize()[0] == 80 && stats->GetImageSize()[1] == 80 &&
           stats->GetImageSampleDistance() == 2.5,
         label + ": 80 x 80 rays at distance 2.5") &&
    ok;
  // Below 1 is 1: no supersampling.
  scene.Mapper->SetImageSampleDistance(0.5f);
  scene.Window->Render();
  ok = Expect(stats->GetImageSize()[0] == 200 && stats->GetImageSampleDistance() == 1.0,
         label + ": a distance below 1 casts one ray per pixel") &&
    ok;
  ok = Expect(scene.Warnings->Count == 0, label + ": no warning") && ok;
  return ok;
}

// A desired update rate no frame can meet, then the still rate.
bool TestAdjusted(vtkUnstructuredGrid* grid, int pipeline)
{
  double range[2];
  grid->GetPointData()->GetScalars()->GetRange(range);
  trctest::WatchedVolume scene(
    grid, trctest::MakeProperty(range[0], range[1], grid->GetLength() / 10), 200);
  scene.Mapper->SetPipeline(pipeline);
  scene.Mapper->SynchronousStatisticsOn(); // every frame timed
  scene.Mapper->SetMaximumImageSampleDistance(4.0f);
  vtkTiledRayCastStatistics* stats = scene.Mapper->GetStatistics();
  const std::string label =
    pipeline == vtkTiledRayCastVolumeMapper::COMPUTE_PIPELINE ? "compute" : "fragment";
  bool ok = true;
  scene.Window->Render();
  ok =
    Expect(stats->GetImageSampleDistance() == 1.0, label + ": the first frame has every ray") && ok;
  scene.Window->SetDesiredUpdateRate(1e5); // 10 microseconds a frame
  double coarsest = 1.0;
  for (int i = 0; i < 4; ++i)
  {
    scene.Renderer->GetActiveCamera()->Azimuth(10);
    scene.Window->Render();
    coarsest = std::max(coarsest, stats->GetImageSampleDistance());
  }
  std::cout << label << ": interacting at an impossible rate, sample distance " << coarsest << " ("
            << stats->GetImageSize()[0] << "x" << stats->GetImageSize()[1] << " rays)\n";
  ok = Expect(coarsest == 4.0, label + ": interaction takes the maximum distance") && ok;
  ok = Expect(stats->GetImageSize()[0] == 50, label + ": 50 x 50 rays") && ok;
  scene.Window->SetDesiredUpdateRate(0.0001); // vtkRenderWindowInteractor's still rate
  ok = trctest::CheckAgainstReference(scene.Window, scene.Renderer, scene.Volume, trctest::Bounds(),
         (label + ", camera stopped").c_str()) &&
    ok;
  ok = Expect(stats->GetImageSampleDistance() == 1.0, label + ": still, every ray again") && ok;
  // A maximum of 1 keeps every ray whatever the rate.
  scene.Mapper->SetMaximumImageSampleDistance(1.0f);
  scene.Window->SetDesiredUpdateRate(1e5);
  scene.Window->Render();
  ok = Expect(stats->GetImageSampleDistance() == 1.0, label + ": a maximum of 1") && ok;
  ok = Expect(scene.Warnings->Count == 0, label + ": no warning") && ok;
  return ok;
}
}

int TestTiledRayCastInteraction(int argc, char* argv[])
{
  vtkSmartPointer<vtkUnstructuredGrid> fin = trctest::ReadMesh(argc, argv, "bluntfin_tets.vtu");
  if (!fin)
  {
    return EXIT_FAILURE;
  }
  if (!trctest::RenderingSupported())
  {
    return VTK_SKIP_RETURN_CODE;
  }
  const int compute = vtkTiledRayCastVolumeMapper::COMPUTE_PIPELINE;
  const int fragment = vtkTiledRayCastVolumeMapper::FRAGMENT_PIPELINE;
  bool ok = TestFixedDistance(fin, compute, false);
  ok = TestFixedDistance(fin, fragment, false) && ok;
  ok = TestFixedDistance(fin, compute, true) && ok;
  ok = TestAdjusted(fin, compute) && ok;
  ok = TestAdjusted(fin, fragment) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
