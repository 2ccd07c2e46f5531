/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTiledRayCastUpdates.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The mapper re-does only what changed, frees everything on request and renders again
// afterwards, and works in viewports that are not the whole window, in several renderers and in
// several windows. Every image is checked against the exact reference renderer.
#include "TiledRayCastTestScene.h"

#include "vtkCommand.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTetMeshValidationReport.h"
#include "vtkWindowToImageFilter.h"

namespace
{
using trctest::Expect;
vtkIdType Uploaded(vtkTiledRayCastVolumeMapper* mapper)
{
  return mapper->GetStatistics()->GetUploadedBytes();
}
// The volume in a viewport that is not the whole window, next to another renderer, with its
// statistics read every frame.
struct Scene
{
  vtkSmartPointer<vtkUnstructuredGrid> Grid;
  const trctest::Bounds Bounds;
  vtkNew<vtkTiledRayCastVolumeMapper> Mapper;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderer> Other;
  vtkNew<vtkRenderWindow> Window;

  explicit Scene(vtkUnstructuredGrid* grid)
    : Grid(grid)
  {
    this->Mapper->SetInputData(grid);
    this->Mapper->SynchronousStatisticsOn();
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(trctest::MakePropertyFor(grid, 0.1));
    this->Renderer->AddVolume(this->Volume);
    this->Renderer->SetBackground(0.2, 0.1, 0.1);
    this->Renderer->SetViewport(0.0, 0.0, 0.6, 1.0);
    this->Other->SetViewport(0.6, 0.0, 1.0, 1.0);
    this->Other->SetBackground(0.1, 0.2, 0.1);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(160, 100);
    this->Window->AddRenderer(this->Renderer);
    this->Window->AddRenderer(this->Other);
    this->Renderer->ResetCamera();
  }

  // The volume's renderer of the last frame against the exact reference.
  bool Matches(const char* label)
  {
    return trctest::CheckAgainstReference(
      this->Window, this->Renderer, this->Volume, this->Bounds, label);
  }
};

// The first frame in a viewport that is not the whole window, the volume in a second renderer
// too and removed from it, then a camera move.
bool Viewports(Scene& s)
{
  bool ok = true;
  s.Window->Render();
  ok = Expect(Uploaded(s.Mapper) > 0, "the first frame uploads the mesh") && ok;
  ok = Expect(s.Mapper->GetStatistics()->GetTotalGPUTime() >= 0, "GPU times are measured") && ok;
  ok = s.Matches("viewport") && ok;

  // The same volume in the second renderer too.
  s.Other->AddVolume(s.Volume);
  s.Other->ResetCamera();
  s.Other->GetActiveCamera()->Azimuth(90);
  s.Other->ResetCameraClippingRange();
  s.Window->Render();
  ok =
    trctest::CheckAgainstReference(s.Window, s.Other, s.Volume, s.Bounds, "second renderer") && ok;
  // vtkViewport::RemoveViewProp releases the prop's graphics resources: the next frame uploads
  // everything again.
  s.Other->RemoveVolume(s.Volume);
  s.Window->Render();
  ok = Expect(Uploaded(s.Mapper) > 0, "removed from a renderer: uploaded again") && ok;

  // Only the camera moves: nothing is uploaded.
  s.Renderer->GetActiveCamera()->Azimuth(40);
  s.Renderer->ResetCameraClippingRange();
  s.Window->Render();
  ok = Expect(Uploaded(s.Mapper) == 0, "a camera move uploads nothing") && ok;
  ok = s.Matches("camera moved") && ok;
  return ok;
}

// The scene's depth is copied only when something may have drawn it: an opaque sphere in the
// volume ends the rays at its surface; once it is removed the rays run to the far plane again
// (a stale copy of its depth would still stop them there).
bool SceneDepth(Scene& s)
{
  bool ok = true;
  ok = Expect(!s.Mapper->GetStatistics()->GetSceneDepthCopied(), "volumes only: no depth copied") &&
    ok;
  auto ball = trctest::MakeBall(s.Volume->GetCenter(), 0.15 * s.Volume->GetLength(), 24);
  s.Renderer->AddActor(ball);
  s.Window->Render();
  ok =
    Expect(s.Mapper->GetStatistics()->GetSceneDepthCopied(), "an opaque actor: depth copied") && ok;
  ok = s.Matches("opaque sphere") && ok;
  s.Renderer->RemoveActor(ball);
  s.Window->Render();
  ok =
    Expect(!s.Mapper->GetStatistics()->GetSceneDepthCopied(), "actor removed: no depth copied") &&
    ok;
  ok = s.Matches("sphere removed") && ok;
  return ok;
}

// Shading: lights are uniforms of the frame. A camera move carries the headlight along, a scene
// light added or moved relights the volume; none uploads anything.
bool Shading(Scene& s)
{
  bool ok = true;
  vtkVolumeProperty* shaded = s.Volume->GetProperty();
  shaded->ShadeOn();
  shaded->SetSpecular(0.5);
  shaded->SetSpecularPower(20.0);
  s.Window->Render();
  ok = s.Matches("shaded") && ok;
  s.Renderer->GetActiveCamera()->Azimuth(-25);
  s.Renderer->ResetCameraClippingRange();
  s.Window->Render();
  ok = Expect(Uploaded(s.Mapper) == 0, "shaded: a camera move uploads nothing") && ok;
  ok = s.Matches("shaded, camera moved") && ok;
  vtkNew<vtkLight> sceneLight;
  sceneLight->SetLightTypeToSceneLight();
  const double* centre = s.Volume->GetCenter();
  sceneLight->SetFocalPoint(centre);
  sceneLight->SetPosition(centre[0] + 1.0, centre[1] + 2.0, centre[2] - 3.0);
  sceneLight->SetDiffuseColor(1.0, 0.7, 0.4);
  s.Renderer->AddLight(sceneLight);
  s.Window->Render();
  ok = Expect(Uploaded(s.Mapper) == 0, "shaded: a light added uploads nothing") && ok;
  ok = s.Matches("shaded, light added") && ok;
  sceneLight->SetPosition(centre[0] - 3.0, centre[1] + 1.0, centre[2]);
  s.Window->Render();
  ok = s.Matches("shaded, light moved") && ok;
  s.Renderer->RemoveLight(sceneLight);
  shaded->ShadeOff();
  return ok;
}

// A new transfer function, then moving points: each uploads only what changed.
bool TransferFunctionAndPoints(Scene& s)
{
  bool ok = true;
  // The transfer function changes: only its nodes are uploaded.
  const vtkIdType meshBytes = s.Mapper->GetStatistics()->GetMeshBytes();
  s.Volume->GetProperty()->GetScalarOpacity()->AddPoint(
    s.Grid->GetPointData()->GetScalars()->GetRange()[1] * 0.9, 0.9);
  s.Window->Render();
  ok = Expect(Uploaded(s.Mapper) > 0 && Uploaded(s.Mapper) < meshBytes / 10,
         "a transfer-function change uploads only the transfer function (" +
           std::to_string(Uploaded(s.Mapper)) + " B)") &&
    ok;
  ok = s.Matches("new transfer function") && ok;

  // The points move (a deforming mesh): only the points are uploaded.
  vtkPoints* points = s.Grid->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    p[2] += 0.05 * std::sin(p[0]);
    points->SetPoint(i, p);
  }
  points->Modified();
  // Straight to the GPU (the default where the renderer is a GPU; asked for here, as llvmpipe
  // would take the CPU's path): the input's coordinates as they are, and once the point order
  // and the tetrahedra's flags that the GPU's check reads.
  s.Mapper->SetPointUpdateToGPU();
  s.Window->Render();
  const vtkIdType numPoints = s.Grid->GetNumberOfPoints();
  const vtkIdType numTets = s.Mapper->GetValidationReport()->GetNumberOfTetrahedra();
  const vtkIdType coordinateBytes = 3 * numPoints * points->GetData()->GetDataTypeSize();
  const vtkIdType firstMotionBytes = coordinateBytes + 4 * numPoints + 4 * ((numTets + 3) / 4);
  ok = Expect(Uploaded(s.Mapper) == firstMotionBytes,
         "moving points on the GPU uploads the coordinates, the point order and the flags (" +
           std::to_string(Uploaded(s.Mapper)) + " B, " + std::to_string(firstMotionBytes) +
           " expected)") &&
    ok;
  ok = Expect(s.Mapper->GetStatistics()->GetMeshRebuild() ==
           vtkTiledRayCastStatistics::MeshRebuildPointsOnGPU,
         "moving points moves them on the GPU (MeshRebuild)") &&
    ok;
  ok = s.Matches("moved points, on the GPU") && ok;
  vtkNew<vtkPoints> moved; // where the next stages start from
  moved->DeepCopy(points);
  // Moved again: the coordinates only.
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    p[1] += 0.02 * std::cos(p[2]);
    points->SetPoint(i, p);
  }
  points->Modified();
  s.Window->Render();
  ok = Expect(Uploaded(s.Mapper) == coordinateBytes,
         "moving them again uploads the coordinates only (" + std::to_string(Uploaded(s.Mapper)) +
           " B)") &&
    ok;
  ok = s.Matches("moved again, on the GPU") && ok;
  // A camera move after it: nothing moves, nothing is uploaded.
  s.Renderer->GetActiveCamera()->Azimuth(5);
  s.Window->Render();
  ok = Expect(Uploaded(s.Mapper) == 0 && s.Mapper->GetStatistics()->GetMeshRebuild() == 0,
         "a camera move after moving points on the GPU uploads and rebuilds nothing") &&
    ok;
  ok = s.Matches("moved on the GPU, camera moved") && ok;

  // The CPU's path: the layout's point texels, 16 B a point.
  s.Mapper->SetPointUpdateToCPU();
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    p[0] -= 0.02 * std::sin(p[1]);
    points->SetPoint(i, p);
  }
  points->Modified();
  s.Window->Render();
  const vtkIdType pointBytes = 16 * numPoints;
  ok = Expect(Uploaded(s.Mapper) == pointBytes,
         "moving points on the CPU uploads the points only (" + std::to_string(Uploaded(s.Mapper)) +
           " B, " + std::to_string(pointBytes) + " expected)") &&
    ok;
  ok = Expect(s.Mapper->GetStatistics()->GetMeshRebuild() ==
           vtkTiledRayCastStatistics::MeshRebuildPoints,
         "moving points on the CPU rebuilds the points only (MeshRebuild)") &&
    ok;
  ok = s.Matches("moved points, on the CPU") && ok;
  s.Mapper->SetPointUpdateToAutomatic();
  points->DeepCopy(moved);
  points->Modified();
  return ok;
}

// The window's pixels of the last frame.
std::vector<unsigned char> Pixels(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkDataArray* rgb = grab->GetOutput()->GetPointData()->GetScalars();
  const auto* first = static_cast<const unsigned char*>(rgb->GetVoidPointer(0));
  return std::vector<unsigned char>(first, first + rgb->GetNumberOfValues());
}

// A deforming mesh over 10 frames, each against the exact reference (the motions of
// Examples/Python/deforming_mesh.py): five of a wave along z, then five that flatten the mesh
// along z, turn it inside out (every tetrahedron inverts: the mapper reorients them) and bring
// it back. Played on the CPU's path, then on the GPU's (PointUpdate), whose frames must be
// the CPU's to the bit. The points are put back at the end.
bool DeformingFrames(Scene& s)
{
  bool ok = true;
  vtkPoints* points = s.Grid->GetPoints();
  vtkNew<vtkPoints> rest;
  rest->DeepCopy(points);
  double centre[3];
  s.Grid->GetCenter(centre);
  const double size = s.Grid->GetLength();
  std::vector<std::vector<unsigned char>> cpuFrames;
  int gpuFrames = 0; // frames moved on the GPU alone
  for (const bool onGPU : { false, true })
  {
    s.Mapper->SetPointUpdate(onGPU ? vtkTiledRayCastVolumeMapper::GPU_POINT_UPDATE
                                   : vtkTiledRayCastVolumeMapper::CPU_POINT_UPDATE);
    for (int frame = 0; frame < 10; ++frame)
    {
      const bool wave = frame < 5;
      const double phase = wave ? 0.7 * frame : vtkMath::Pi() * (frame - 4) / 3.0;
      for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
      {
        double p[3];
        rest->GetPoint(i, p);
        p[2] = wave ? p[2] + 0.03 * size * std::sin(6.0 * (p[0] - centre[0]) / size + phase)
                    : centre[2] + (p[2] - centre[2]) * std::cos(phase);
        points->SetPoint(i, p);
      }
      points->Modified();
      s.Window->Render();
      const std::string label = std::string(wave ? "wave" : "inside out") + ", deforming frame " +
        std::to_string(frame + 1) + (onGPU ? " (points on the GPU)" : " (points on the CPU)");
      // The statistics say what was rebuilt: the points, or everything in the two frames where
      // the mesh turns inside out or back (the tetrahedra are reoriented by a full build).
      vtkTiledRayCastStatistics* stats = s.Mapper->GetStatistics();
      std::cout << label << ": mesh rebuild " << stats->GetMeshRebuild() << " in "
                << 1000 * stats->GetMeshBuildTime() << " ms\n";
      const int all = vtkTiledRayCastStatistics::MeshRebuildScalars |
        vtkTiledRayCastStatistics::MeshRebuildPoints |
        vtkTiledRayCastStatistics::MeshRebuildTopology;
      // On the GPU, the CPU rebuilds nothing, not even in a frame where the automatic
      // integration makes its choice again (the longest edge changed by a step): the choice
      // samples the moved points where they are (vtkTiledRayCastIntegration).
      const int rebuild = stats->GetMeshRebuild();
      const int onCPU = vtkTiledRayCastStatistics::MeshRebuildPoints;
      const int moved = vtkTiledRayCastStatistics::MeshRebuildPointsOnGPU;
      const bool flips = frame == 6 || frame == 9;
      const bool pointsOnly = rebuild == (onGPU ? moved : onCPU);
      ok = Expect(flips ? rebuild == all : pointsOnly,
             label + (flips ? ": turned over, a full rebuild" : ": the points only")) &&
        ok;
      gpuFrames += onGPU && !flips && rebuild == moved ? 1 : 0;
      ok = s.Matches(label.c_str()) && ok;
      if (!onGPU)
      {
        cpuFrames.push_back(Pixels(s.Window));
        continue;
      }
      const std::vector<unsigned char> gpuFrame = Pixels(s.Window);
      int largest = 0;
      for (size_t k = 0; k < gpuFrame.size() && k < cpuFrames[frame].size(); ++k)
      {
        largest = std::max(largest, std::abs(gpuFrame[k] - cpuFrames[frame][k]));
      }
      ok = Expect(gpuFrame.size() == cpuFrames[frame].size() && largest == 0,
             label + ": the same pixels as the CPU's path (largest difference " +
               std::to_string(largest) + ")") &&
        ok;
    }
  }
  ok = Expect(gpuFrames == 8,
         std::to_string(gpuFrames) + " of the 8 frames without a flip moved on the GPU alone") &&
    ok;

  // A coordinate turned NaN in a frame moved on the GPU: the GPU's check refuses it, the CPU's
  // build says why once, nothing is drawn; put back, the mesh is drawn again.
  points->DeepCopy(rest);
  points->Modified();
  s.Window->Render();
  double p[3];
  points->GetPoint(7, p);
  const double kept = p[1];
  p[1] = std::nan("");
  points->SetPoint(7, p);
  points->Modified();
  vtkNew<trctest::MessageCounter> errors;
  const unsigned long tag = s.Mapper->AddObserver(vtkCommand::ErrorEvent, errors);
  s.Window->Render();
  ok = Expect(errors->Errors == 1 && errors->LastError.find("NaN") != std::string::npos,
         "a NaN coordinate under motion on the GPU: one error naming it (" + errors->LastError +
           ")") &&
    ok;
  p[1] = kept;
  points->SetPoint(7, p);
  points->Modified();
  s.Window->Render();
  s.Mapper->RemoveObserver(tag);
  ok = Expect(errors->Errors == 1, "put back: drawn again without another error") && ok;
  ok = s.Matches("NaN put back") && ok;
  s.Mapper->SetPointUpdateToAutomatic();
  points->DeepCopy(rest);
  points->Modified();
  return ok;
}

// Everything freed, then rendered again; the same mapper in a second window and back.
bool ReleaseAndSecondWindow(Scene& s)
{
  bool ok = true;
  // Everything freed, then rendered again.
  s.Mapper->ReleaseGraphicsResources(s.Window);
  ok = Expect(s.Mapper->GetStatistics()->GetTotalGPUBytes() == 0, "released: no GPU memory held") &&
    ok;
  s.Window->Render();
  ok = Expect(Uploaded(s.Mapper) > 0, "after release, the mesh is uploaded again") && ok;
  ok = s.Matches("after release") && ok;

  // The same mapper in a second window (another context): it moves there and back.
  {
    vtkNew<vtkRenderer> renderer2;
    renderer2->AddVolume(s.Volume);
    vtkNew<vtkRenderWindow> window2;
    window2->SetMultiSamples(0);
    window2->SetSize(90, 70);
    window2->AddRenderer(renderer2);
    renderer2->ResetCamera();
    window2->Render();
    // This deformed mesh at 90x70 once lost one pixel's ray (36/255 darker): its centre lies
    // 0.005 px from a point where the boundary folds, and the rasteriser's snapping moved it out
    // of the deeper sheet's front faces. Exact coverage (vtkTiledRayCastBoundaryFaceVS.glsl)
    // keeps it: the default bounds hold.
    ok =
      trctest::CheckAgainstReference(window2, renderer2, s.Volume, s.Bounds, "second window") && ok;
    renderer2->RemoveVolume(s.Volume);
  }
  s.Window->Render();
  ok = s.Matches("back in the first") && ok;
  return ok;
}

// The paper's layout in both pipelines, then its multi-pass scheme with occlusion queries.
bool PipelinesAndPasses(Scene& s)
{
  bool ok = true;
  // The paper's layout in the compute pipeline, then the fragment pipeline on the same mapper:
  // a switch of pipeline frees the other's per-pixel memory and draws the same picture.
  s.Mapper->SetMeshLayoutToPaper();
  s.Window->Render();
  ok = s.Matches("compute, paper layout") && ok;
  const vtkIdType computeTargets = s.Mapper->GetStatistics()->GetRenderTargetBytes();
  s.Mapper->SetPipelineToFragment();
  s.Window->Render();
  ok = s.Matches("fragment, paper layout") && ok;
  ok = Expect(s.Mapper->GetStatistics()->GetRenderTargetBytes() > 2 * computeTargets,
         "the compute pipeline holds less than half the fragment pipeline's target memory (" +
           std::to_string(computeTargets) + " B against " +
           std::to_string(s.Mapper->GetStatistics()->GetRenderTargetBytes()) + " B)") &&
    ok;

  // Paper layout and the multi-pass scheme on the same data.
  s.Mapper->SetTetsPerPass(2);
  s.Mapper->SetTileSize(32);
  s.Window->Render();
  ok = s.Matches("paper, 2 tets/pass") && ok;
  const int passesEvery4 = s.Mapper->GetStatistics()->GetMaximumPassesPerTile();
  // 32 px tiles over 96x100: the corners the mesh leaves empty are skipped.
  const int tiles = s.Mapper->GetStatistics()->GetNumberOfTiles();
  const int skipped = s.Mapper->GetStatistics()->GetNumberOfTilesSkipped();
  ok = Expect(tiles == 12 && skipped > 0 && skipped < tiles,
         "empty tiles are skipped (" + std::to_string(skipped) + " of " + std::to_string(tiles) +
           ")") &&
    ok;

  // A query after every pass: each round then has a single pass, whose progress the Z-update must
  // carry over (it once did not, and this looped until the pass limit). Checking more often
  // can only end a tile sooner.
  s.Mapper->SetOcclusionQueryInterval(1);
  s.Mapper->SetMaximumNumberOfPassesPerLayer(5000);
  s.Window->Render();
  ok = s.Matches("paper, 2 tets/pass, query every pass") && ok;
  const int passesEvery1 = s.Mapper->GetStatistics()->GetMaximumPassesPerTile();
  ok = Expect(passesEvery1 <= passesEvery4,
         "queries after every pass: at most as many passes per tile (" +
           std::to_string(passesEvery1) + " against " + std::to_string(passesEvery4) + ")") &&
    ok;
  return ok;
}
} // namespace

int TestTiledRayCastUpdates(int argc, char* argv[])
{
  vtkSmartPointer<vtkUnstructuredGrid> grid = trctest::ReadMesh(argc, argv, "spx_vistrails.vtu");
  if (!grid)
  {
    return EXIT_FAILURE;
  }
  Scene s(grid);
  bool ok = true;
  for (auto stage : { Viewports, SceneDepth, Shading, TransferFunctionAndPoints, DeformingFrames,
         ReleaseAndSecondWindow, PipelinesAndPasses })
  {
    ok = stage(s) && ok;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
