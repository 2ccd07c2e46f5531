/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTiledRayCastTranslucent.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Translucent geometry in depth order with the volume (docs/mapper.md, "Translucent geometry"):
// with vtkRenderer::UseDepthPeelingForVolumes the compute pipeline takes part in VTK's dual depth
// peeling, and the image is checked against the exact reference with the translucent surfaces
// as layers of fragments (vtkTetReferenceRenderer::AddTranslucentLayer): a translucent sphere and
// a translucent plane cutting the volume, seen from outside and with the camera inside the
// volume and the sphere. VTK's projected tetrahedra mapper's error on the same scene (drawn after
// the translucent geometry, VTK's order) is printed beside. Without the switch the translucent-
// geometry warning stays; with it, it is gone.
#include "TiledRayCastTestScene.h"
#include "TiledRayCastTranslucentScene.h"

#include "vtkPointData.h"
#include "vtkProjectedTetrahedraMapper.h"
#include "vtkTesting.h"

#include <cmath>
#include <string>

namespace
{
using trctest::Expect;

// The volume, a translucent sphere around part of it and a translucent plane through it, with
// VTK's dual depth peeling.
struct Scene
{
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkTiledRayCastVolumeMapper> Mapper;
  vtkNew<trctest::MessageCounter> Warnings;
  trcscene::TranslucentGeometry Translucent;

  Scene(vtkUnstructuredGrid* grid, vtkVolumeProperty* property, int size)
    : Translucent(grid, this->Renderer)
  {
    this->Mapper->SetInputData(grid);
    this->Mapper->SynchronousStatisticsOn();
    this->Mapper->AddObserver(vtkCommand::WarningEvent, this->Warnings);
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(property);
    this->Renderer->AddVolume(this->Volume);
    this->Renderer->SetBackground(0.1, 0.1, 0.15);
    this->Window->SetMultiSamples(0);
    this->Window->SetAlphaBitPlanes(1);
    this->Window->SetSize(size, size);
    this->Window->AddRenderer(this->Renderer);
    // The benchmarks' view (BenchmarkFrames.h): the whole scene, turned.
    this->Renderer->ResetCamera();
    this->Renderer->GetActiveCamera()->Elevation(20);
    this->Renderer->GetActiveCamera()->Azimuth(30);
    this->Renderer->ResetCameraClippingRange();
  }

  vtkSmartPointer<vtkUnsignedCharArray> Pixels()
  {
    int* size = this->Window->GetSize();
    auto pixels = vtkSmartPointer<vtkUnsignedCharArray>::New();
    this->Window->GetPixelData(0, 0, size[0] - 1, size[1] - 1, 0, pixels, 0);
    return pixels;
  }

  void Show(bool volume, bool sphere, bool plane)
  {
    this->Volume->SetVisibility(volume);
    this->Translucent.Show(sphere, plane);
  }

  // The fragments of `actor` (index 0: the sphere, 1: the plane) as the reference's layers: those
  // facing the camera, then those facing away, each drawn alone and opaque and read from the
  // depth buffer; premultiplied (colour, opacity) where a fragment is.
  void AddLayers(vtkTetReferenceRenderer* reference, int index)
  {
    vtkActor* actor = index == 0 ? this->Translucent.Sphere : this->Translucent.Plane;
    vtkProperty* property = actor->GetProperty();
    const double opacity = this->Translucent.Opacity[index];
    double color[3];
    property->GetAmbientColor(color);
    this->Show(false, index == 0, index == 1);
    property->SetOpacity(1.0);
    int* size = this->Window->GetSize();
    const vtkIdType pixels = static_cast<vtkIdType>(size[0]) * size[1];
    for (int facing = 0; facing < 2; ++facing)
    {
      property->SetBackfaceCulling(facing == 0);
      property->SetFrontfaceCulling(facing == 1);
      this->Window->Render();
      vtkNew<vtkFloatArray> depth;
      this->Window->GetZbufferData(0, 0, size[0] - 1, size[1] - 1, depth);
      vtkNew<vtkFloatArray> rgba;
      rgba->SetNumberOfComponents(4);
      rgba->SetNumberOfTuples(pixels);
      for (vtkIdType i = 0; i < pixels; ++i)
      {
        const bool fragment = depth->GetValue(i) < 1.f;
        for (int c = 0; c < 3; ++c)
        {
          rgba->SetComponent(i, c, fragment ? color[c] * opacity : 0.0);
        }
        rgba->SetComponent(i, 3, fragment ? opacity : 0.0);
      }
      reference->AddTranslucentLayer(rgba, depth);
    }
    property->SetBackfaceCulling(false);
    property->SetFrontfaceCulling(false);
    property->SetOpacity(opacity);
  }

  // The window's image against the exact reference of the volume and the translucent layers
  // over the background, within `bounds`.
  bool Check(const trctest::Bounds& bounds, const std::string& label)
  {
    this->Show(false, false, false);
    this->Window->Render();
    vtkSmartPointer<vtkUnsignedCharArray> behind = this->Pixels();
    vtkNew<vtkTetReferenceRenderer> reference;
    this->AddLayers(reference, 0);
    this->AddLayers(reference, 1);
    this->Show(true, true, true);
    this->Window->Render();
    vtkSmartPointer<vtkUnsignedCharArray> pixels = this->Pixels();
    int* size = this->Window->GetSize();
    reference->SetInputData(this->Mapper->GetInput());
    reference->SetVolumeProperty(this->Volume->GetProperty());
    reference->SetVolume(this->Volume);
    reference->SetCamera(this->Renderer->GetActiveCamera());
    reference->SetImageSize(size[0], size[1]);
    return trctest::CompareWithReference(
      reference, behind, pixels, size[0], size[1], bounds, label, this->Mapper);
  }
};

// How many warnings of the mapper's own (not those of the mesh's validation) were given.
int MapperWarnings(Scene& scene)
{
  const std::string& text = scene.Warnings->Text;
  int count = 0;
  for (const char* what : { "Translucent polygonal geometry", "drawn on its own", "rays" })
  {
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
    {
      ++count;
    }
  }
  return count;
}

// No warning, and the volume drawn by the compute pipeline in the peeling's every stage: once
// before the peels and once in each peel.
bool TookPart(Scene& scene, const std::string& label)
{
  vtkTiledRayCastStatistics* stats = scene.Mapper->GetStatistics();
  bool ok = Expect(MapperWarnings(scene) == 0, label + ": no warning");
  ok = Expect(std::string(stats->GetPipeline()) == "Compute" && stats->GetDepthPeelingStage() > 0 &&
           stats->GetNumberOfDepthPeelingDraws() >= 3,
         label + ": drawn inside VTK's depth peeling, in three stages or more") &&
    ok;
  // The draws after the first traverse the entries it listed (llvmpipe and current GPUs can
  // clear the list's heads in place).
  ok = Expect(stats->GetDepthPeelingEntriesReused(),
         label + ": the last draw traversed the first draw's entries") &&
    ok;
  if (!ok)
  {
    std::cerr << scene.Warnings->Text << "\n";
  }
  return ok;
}

// VTK's dual depth peeling keeps its colours in 8-bit textures (RGBA8) between peels: each peel
// rounds the front colour so far and the back one once more than a framebuffer does.
trctest::Bounds PeelingBounds()
{
  trctest::Bounds bounds;
  bounds.RMSE = 1.0;
  bounds.P999 = 3.0;
  bounds.Max = 4.0;
  return bounds;
}

// Bounds that any image meets: for figures printed, not checked.
trctest::Bounds AnyDifference()
{
  trctest::Bounds any;
  any.RMSE = any.P999 = any.Max = 255;
  return any;
}

// The scene from outside, then with the camera inside the volume and the sphere: within the
// bounds, silently, the compute pipeline taking part in every stage of the peeling.
bool TestPeeling(vtkUnstructuredGrid* grid)
{
  // Optical depth well above 1 across the mesh, so that the order matters.
  Scene scene(grid, trctest::MakePropertyFor(grid, 0.15), 128);
  const trctest::Bounds bounds = PeelingBounds();
  bool ok = scene.Check(bounds, "outside");
  ok = TookPart(scene, "outside") && ok;

  // The camera inside the volume and the sphere.
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  double center[3];
  scene.Translucent.SphereSource->GetCenter(center);
  camera->SetFocalPoint(center[0] - 1, center[1], center[2]);
  camera->SetPosition(center);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(70);
  scene.Renderer->ResetCameraClippingRange();
  camera->SetClippingRange(0.01 * grid->GetLength(), 3 * grid->GetLength());
  ok = scene.Check(bounds, "camera inside") && ok;
  ok = TookPart(scene, "camera inside") && ok;
  return ok;
}

// An optically thick volume (unit distance 0.4 % of the diagonal: optical depth in the tens
// across the torus), so that each range's early termination and the fragments in front of
// and behind saturated stretches are exercised; and the volume's values far from zero (the
// scalars shifted by 1e4, the transfer function with them).
bool TestThick(vtkUnstructuredGrid* grid)
{
  vtkNew<vtkUnstructuredGrid> shifted;
  shifted->DeepCopy(grid);
  vtkDataArray* scalars = shifted->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < scalars->GetNumberOfTuples(); ++i)
  {
    scalars->SetComponent(i, 0, scalars->GetComponent(i, 0) + 1e4);
  }
  Scene scene(shifted, trctest::MakePropertyFor(shifted, 0.004), 128);
  const trctest::Bounds bounds = PeelingBounds();
  bool ok = scene.Check(bounds, "optically thick, scalars near 1e4");
  return TookPart(scene, "optically thick") && ok;
}

// One peel where three are needed: the pass draws the volume a third time for what the peel
// left (the remainder, alpha blended: VTK's approximation for its own fragments too, so the
// image is only near the reference there).
bool TestRemainder(vtkUnstructuredGrid* grid)
{
  Scene scene(grid, trctest::MakePropertyFor(grid, 0.15), 128);
  scene.Renderer->SetMaximumNumberOfPeels(1);
  scene.Check(AnyDifference(), "one peel and the remainder");
  vtkTiledRayCastStatistics* stats = scene.Mapper->GetStatistics();
  return Expect(MapperWarnings(scene) == 0 && stats->GetDepthPeelingStage() == 3 &&
      stats->GetNumberOfDepthPeelingDraws() == 3 && stats->GetDepthPeelingEntriesReused(),
    "one peel: drawn before it, in it and for the remainder, silently");
}

// Without depth peeling for volumes: the volume drawn over the translucent geometry, the warning
// once (VTK's projected tetrahedra mapper does the same without a word); VTK's projected
// tetrahedra's error on the peeled scene printed beside ours.
bool TestWithoutPeelingForVolumes(vtkUnstructuredGrid* grid)
{
  Scene scene(grid, trctest::MakePropertyFor(grid, 0.15), 128);
  scene.Renderer->SetUseDepthPeelingForVolumes(0);
  scene.Check(
    AnyDifference(), "without depth peeling for volumes (volume over the translucent geometry)");
  bool ok = Expect(MapperWarnings(scene) == 1 &&
      scene.Warnings->Text.find("Translucent polygonal geometry") != std::string::npos &&
      scene.Mapper->GetStatistics()->GetDepthPeelingStage() == 0,
    "without depth peeling for volumes: the translucent-geometry warning, once");

  // VTK's projected tetrahedra on the same scene (its own order: volume over the geometry).
  vtkNew<vtkProjectedTetrahedraMapper> projected;
  projected->SetInputData(scene.Mapper->GetInput());
  scene.Volume->SetMapper(projected);
  scene.Check(AnyDifference(), "VTK's projected tetrahedra, same scene");
  return ok;
}
} // namespace

int TestTiledRayCastTranslucent(int argc, char* argv[])
{
  if (!trctest::RenderingSupported())
  {
    std::cout << "OpenGL cannot run the mapper here; skipped.\n";
    return VTK_SKIP_RETURN_CODE;
  }
  vtkSmartPointer<vtkUnstructuredGrid> grid = trctest::ReadMesh(argc, argv, "torus_vistrails.vtu");
  if (!grid)
  {
    return EXIT_FAILURE;
  }
  bool ok = TestPeeling(grid);
  ok = TestRemainder(grid) && ok;
  ok = TestThick(grid) && ok;
  ok = TestWithoutPeelingForVolumes(grid) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
