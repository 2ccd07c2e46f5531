/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTiledRayCastCoverage.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Every ray that enters the mesh is found, however the boundary is drawn: meshes rendered at
// odd image sizes from several views, each image checked against the exact reference renderer
// with the default bounds. What this guards against (docs/mapper.md, "Exact coverage"):
// - a pixel centre within the rasteriser's snapping (1/256 px) of a face's edge where the
//   boundary folds, which no front face of the deeper sheet covered (comb_tets: 2 such pixels
//   in these 20 images before);
// - flat tetrahedra on the boundary whose input order faces inwards, culled as back faces
//   (torus_vistrails ships 30: 1,733 pixels wrong in these 20 images before).
// Both pipelines: the compute pipeline lists the same boundary fragments (same coverage test)
// and takes them by the same peeling rules.
#include "TiledRayCastTestScene.h"

int TestTiledRayCastCoverage(int argc, char* argv[])
{
  const char* meshes[] = { "torus_vistrails.vtu", "comb_tets.vtu", "spx_vistrails.vtu" };
  const int sizes[][2] = { { 90, 70 }, { 131, 97 }, { 200, 200 }, { 257, 183 } };
  const double views[][2] = { { 0, 0 }, { 20, 30 }, { 75, -40 }, { 140, 15 }, { 230, 60 } };
  const trctest::Bounds bounds;
  bool ok = true;
  for (int pipeline : { vtkTiledRayCastVolumeMapper::COMPUTE_PIPELINE,
         vtkTiledRayCastVolumeMapper::FRAGMENT_PIPELINE })
    for (const char* file : meshes)
    {
      vtkSmartPointer<vtkUnstructuredGrid> grid = trctest::ReadMesh(argc, argv, file);
      if (!grid)
      {
        return EXIT_FAILURE;
      }
      vtkNew<vtkTiledRayCastVolumeMapper> mapper;
      mapper->SetInputData(grid);
      mapper->SetPipeline(pipeline);
      vtkNew<vtkVolume> volume;
      volume->SetMapper(mapper);
      volume->SetProperty(trctest::MakePropertyFor(grid, 0.1));
      vtkNew<vtkRenderer> renderer;
      renderer->AddVolume(volume);
      vtkNew<vtkRenderWindow> window;
      window->SetMultiSamples(0);
      window->AddRenderer(renderer);
      for (const auto& size : sizes)
      {
        window->SetSize(size[0], size[1]);
        for (const auto& view : views)
        {
          renderer->ResetCamera();
          vtkCamera* camera = renderer->GetActiveCamera();
          camera->Azimuth(view[0]);
          camera->Elevation(view[1]);
          camera->OrthogonalizeViewUp();
          renderer->ResetCameraClippingRange();
          window->Render();
          const std::string label = std::string(mapper->GetPipelineAsString()) + " " + file + " " +
            std::to_string(size[0]) + "x" + std::to_string(size[1]) + " azimuth " +
            std::to_string(int(view[0])) + " elevation " + std::to_string(int(view[1]));
          ok =
            trctest::CheckAgainstReference(window, renderer, volume, bounds, label.c_str()) && ok;
          // Back to the reset camera's direction for the next view.
          camera->Elevation(-view[1]);
          camera->Azimuth(-view[0]);
        }
      }
    }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
