/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTiledRayCastOverlapping.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Overlapping volumes (docs/mapper.md, "Overlapping volumes"): volumes of the mapper whose world
// bounds overlap are integrated in one traversal, their mixture where they overlap, and checked
// against the exact reference's scene of several volumes (vtkTetReferenceRenderer::AddVolume):
// two meshes with different transfer functions and matrices, a mesh inside a larger one, the
// camera inside both; volumes that do not overlap are drawn alone, pixel for pixel as each
// draws by itself; a volume a group cannot take (the fragment pipeline, one past what one
// traversal's texture units hold) warns once and is drawn alone; a steady frame of a group
// composes no GLSL; three or more volumes of the same code share one copy of it
// (vtkTiledRayCastSharedMemberCode), two volumes or volumes of different code (cell scalars,
// empty-space skipping) keep a copy each.
#include "TiledRayCastTestScene.h"

#include "vtkActorCollection.h"
#include "vtkCellData.h"
#include "vtkMatrix4x4.h"
#include "vtkProjectedTetrahedraMapper.h"
#include "vtkTesting.h"

#include <array>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
using trctest::Expect;

// Another transfer function than the ramp: other colours, opacity falling over the range.
vtkSmartPointer<vtkVolumeProperty> OtherProperty(vtkDataSet* grid, double fraction)
{
  double range[2];
  grid->GetPointData()->GetScalars()->GetRange(range);
  const double lo = range[0], hi = range[1];
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(lo, 0.9, 0.1, 0.8);
  color->AddRGBPoint(lo + 0.3 * (hi - lo), 0.1, 0.9, 0.9);
  color->AddRGBPoint(hi, 0.9, 0.9, 0.9);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(lo, 0.5);
  opacity->AddPoint(lo + 0.6 * (hi - lo), 0.1);
  opacity->AddPoint(hi, 0.3);
  return trcscene::MakeVolumeProperty(color, opacity, fraction * grid->GetLength());
}

// How many warnings said that a volume is drawn on its own (not those of a mesh's validation).
int GroupWarnings(trctest::MessageCounter* warnings)
{
  int count = 0;
  for (size_t at = warnings->Text.find("drawn on its own"); at != std::string::npos;
       at = warnings->Text.find("drawn on its own", at + 1))
  {
    ++count;
  }
  return count;
}

// `grid`'s volume scaled to `scale` of `around`'s size, turned, its centre at around's centre
// plus `offset` times around's size.
void Place(vtkVolume* volume, vtkDataSet* grid, vtkDataSet* around, double scale,
  const std::array<double, 3>& offset, const std::array<double, 3>& orientation)
{
  double c[3], a[3];
  grid->GetCenter(c);
  around->GetCenter(a);
  const double size = around->GetLength();
  volume->SetOrigin(c);
  volume->SetScale(scale * size / grid->GetLength());
  volume->SetOrientation(orientation[0], orientation[1], orientation[2]);
  volume->SetPosition(
    a[0] - c[0] + offset[0] * size, a[1] - c[1] + offset[1] * size, a[2] - c[2] + offset[2] * size);
}

// Several volumes in one window, each with its own mapper.
struct Scene
{
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  std::vector<vtkSmartPointer<vtkVolume>> Volumes;
  std::vector<vtkSmartPointer<vtkTiledRayCastVolumeMapper>> Mappers;
  vtkNew<trctest::MessageCounter> Warnings;

  explicit Scene(int size)
  {
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(size, size);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->SetBackground(0.1, 0.1, 0.15);
  }

  vtkVolume* Add(vtkUnstructuredGrid* grid, vtkVolumeProperty* property)
  {
    auto mapper = vtkSmartPointer<vtkTiledRayCastVolumeMapper>::New();
    mapper->SetInputData(grid);
    mapper->SynchronousStatisticsOn();
    mapper->AddObserver(vtkCommand::WarningEvent, this->Warnings);
    auto volume = vtkSmartPointer<vtkVolume>::New();
    volume->SetMapper(mapper);
    volume->SetProperty(property);
    this->Renderer->AddVolume(volume);
    this->Volumes.push_back(volume);
    this->Mappers.push_back(mapper);
    return volume;
  }

  // Add(), the volume placed in `around` (Place).
  vtkVolume* AddPlaced(vtkUnstructuredGrid* grid, vtkVolumeProperty* property, vtkDataSet* around,
    double scale, const std::array<double, 3>& offset, const std::array<double, 3>& orientation)
  {
    vtkVolume* volume = this->Add(grid, property);
    Place(volume, grid, around, scale, offset, orientation);
    return volume;
  }

  vtkSmartPointer<vtkUnsignedCharArray> Pixels()
  {
    int* size = this->Window->GetSize();
    auto pixels = vtkSmartPointer<vtkUnsignedCharArray>::New();
    this->Window->GetPixelData(0, 0, size[0] - 1, size[1] - 1, 0, pixels, 0);
    return pixels;
  }

  // Only volume `only` visible, or every volume (-1), or none (-2).
  void Show(int only)
  {
    for (size_t i = 0; i < this->Volumes.size(); ++i)
    {
      this->Volumes[i]->SetVisibility(only == -1 || static_cast<int>(i) == only);
    }
  }
};

// The window's image of every volume against the reference's scene of all of them
// (TiledRayCastTestScene.h's CheckAgainstReference, for several volumes).
bool CheckScene(Scene& scene, const trctest::Bounds& bounds, const std::string& label)
{
  vtkRenderWindow* window = scene.Window;
  int* size = window->GetSize();
  const int width = size[0], height = size[1];
  scene.Show(-2);
  window->Render();
  vtkSmartPointer<vtkUnsignedCharArray> behind = scene.Pixels();
  scene.Show(-1);
  window->Render();
  vtkSmartPointer<vtkUnsignedCharArray> pixels = scene.Pixels();
  vtkNew<vtkFloatArray> depth;
  window->GetZbufferData(0, 0, width - 1, height - 1, depth);

  vtkNew<vtkTetReferenceRenderer> reference;
  vtkVolume* first = scene.Volumes[0];
  reference->SetInputData(scene.Mappers[0]->GetInput());
  reference->SetVolumeProperty(first->GetProperty());
  reference->SetVolume(first);
  for (size_t i = 1; i < scene.Volumes.size(); ++i)
  {
    vtkVolume* v = scene.Volumes[i];
    reference->AddVolume(scene.Mappers[i]->GetInput(), v->GetProperty(), v->GetMatrix());
  }
  reference->SetCamera(scene.Renderer->GetActiveCamera());
  reference->SetImageSize(width, height);
  reference->SetOpaqueDepth(depth);
  return trctest::CompareWithReference(
    reference, behind, pixels, width, height, bounds, label, scene.Mappers[0]);
}

// VTK's projected tetrahedra mapper on the same scene (each volume its own, drawn one after
// another), in a window of its own, against the same reference: its error printed beside ours.
void PrintProjectedTetrahedra(Scene& scene, const std::string& label)
{
  int* size = scene.Window->GetSize();
  Scene projected(size[0]);
  projected.Renderer->SetBackground(scene.Renderer->GetBackground());
  projected.Renderer->GetActiveCamera()->DeepCopy(scene.Renderer->GetActiveCamera());
  vtkActorCollection* actors = scene.Renderer->GetActors();
  actors->InitTraversal();
  while (vtkActor* actor = actors->GetNextActor())
  {
    projected.Renderer->AddActor(actor); // the opaque sphere of "an opaque sphere"
  }
  for (size_t i = 0; i < scene.Volumes.size(); ++i)
  {
    vtkVolume* source = scene.Volumes[i];
    auto* input = vtkUnstructuredGrid::SafeDownCast(scene.Mappers[i]->GetInput());
    vtkVolume* volume = projected.Add(input, source->GetProperty());
    vtkNew<vtkProjectedTetrahedraMapper> mapper;
    mapper->SetInputData(input);
    volume->SetMapper(mapper);
    volume->SetOrigin(source->GetOrigin());
    volume->SetScale(source->GetScale());
    volume->SetOrientation(source->GetOrientation());
    volume->SetPosition(source->GetPosition());
  }
  trctest::Bounds any;
  any.RMSE = any.P999 = any.Max = 1e9;
  CheckScene(projected, any, label + ", VTK's projected tetrahedra");
}

// A scene of volumes that overlap: one traversal with rays through their mixture, within the
// default bounds of the exact reference, silently; VTK's projected tetrahedra's error printed.
// `sharedCode` 1 or 0: whether the traversal must hold one copy of the volumes' code (four or
// more volumes of the same code, vtkTiledRayCastSharedMemberCode) or one per volume.
bool CheckGroup(Scene& scene, const std::string& label, int sharedCode = -1)
{
  bool ok = CheckScene(scene, trctest::Bounds(), label);
  if (sharedCode >= 0)
  {
    ok = Expect(scene.Mappers[0]->GetStatistics()->GetGroupCodeShared() == (sharedCode == 1),
           label + (sharedCode == 1 ? ": one copy of the volumes' code" : ": a copy per volume")) &&
      ok;
  }
  const int volumes = static_cast<int>(scene.Volumes.size());
  for (auto& mapper : scene.Mappers)
  {
    ok = Expect(mapper->GetStatistics()->GetRendered() &&
             mapper->GetStatistics()->GetNumberOfGroupedVolumes() == volumes,
           label + ": every volume drawn in one traversal") &&
      ok;
  }
  ok = Expect(scene.Mappers[0]->GetStatistics()->GetNumberOfMixedRays() > 0,
         label + ": rays through the mixture") &&
    ok;
  ok = Expect(GroupWarnings(scene.Warnings) == 0, label + ": no warning") && ok;
  PrintProjectedTetrahedra(scene, label);
  return ok;
}

// Two meshes with different transfer functions and matrices, overlapping; then the second one
// in the fragment pipeline, which a group does not take: a warning, and drawn alone.
bool TestTwo(vtkUnstructuredGrid* torus, vtkUnstructuredGrid* spx)
{
  Scene scene(128);
  scene.Add(torus, trctest::MakePropertyFor(torus, 0.08));
  vtkVolume* second = scene.AddPlaced(
    spx, OtherProperty(spx, 0.1), torus, 0.7, { 0.15, -0.05, 0.1 }, { 20, 35, -10 });
  scene.Renderer->ResetCamera();
  scene.Renderer->GetActiveCamera()->Elevation(25);
  scene.Renderer->ResetCameraClippingRange();
  bool ok = CheckGroup(scene, "two overlapping", 0);

  // An opaque sphere in the overlap ends every volume's rays at its surface (the scene's depth,
  // which the volumes share).
  auto ball = trctest::MakeBall(second->GetCenter(), 0.12 * torus->GetLength(), 24);
  scene.Renderer->AddActor(ball);
  ok = CheckGroup(scene, "two overlapping, an opaque sphere") && ok;
  scene.Renderer->RemoveActor(ball);

  // Drawn one after the other: the error of compositing overlapping volumes in VTK's order.
  scene.Mappers[1]->SetPipelineToFragment();
  trctest::Bounds any;
  any.RMSE = any.P999 = any.Max = 1e9;
  CheckScene(scene, any, "two overlapping, drawn one by one (not grouped)");
  ok = Expect(GroupWarnings(scene.Warnings) == 1,
         "one warning: the fragment pipeline's volume is drawn on its own") &&
    ok;
  ok = Expect(scene.Mappers[0]->GetStatistics()->GetNumberOfGroupedVolumes() == 1 &&
           scene.Mappers[1]->GetStatistics()->GetNumberOfGroupedVolumes() == 1,
         "no group with the fragment pipeline") &&
    ok;
  scene.Window->Render();
  ok = Expect(GroupWarnings(scene.Warnings) == 1, "warned once") && ok;
  return ok;
}

// A small mesh inside a larger one.
bool TestInside(vtkUnstructuredGrid* outer, vtkUnstructuredGrid* inner)
{
  Scene scene(128);
  scene.Add(outer, trctest::MakePropertyFor(outer, 0.15));
  scene.AddPlaced(
    inner, OtherProperty(inner, 0.02), outer, 0.3, { 0.02, 0.0, -0.02 }, { 0, 60, 30 });
  scene.Renderer->ResetCamera();
  scene.Renderer->GetActiveCamera()->Azimuth(30);
  scene.Renderer->ResetCameraClippingRange();
  bool ok = CheckGroup(scene, "mesh inside a mesh");

  // Where the inner mesh is not on the ray, the group's traversal walks the outer one exactly
  // as it walks alone: the same pixels, alone with the integration a group takes (partial
  // pre-integration; the automatic mode alone may take a table, within 1/255).
  vtkSmartPointer<vtkUnsignedCharArray> group = scene.Pixels();
  for (vtkTiledRayCastVolumeMapper* mapper : scene.Mappers)
  {
    mapper->SetIntegrationModeToPartialPreIntegration();
  }
  scene.Show(-2);
  scene.Window->Render();
  vtkSmartPointer<vtkUnsignedCharArray> background = scene.Pixels();
  scene.Show(0);
  scene.Window->Render();
  vtkSmartPointer<vtkUnsignedCharArray> outerAlone = scene.Pixels();
  scene.Show(1);
  scene.Window->Render();
  vtkSmartPointer<vtkUnsignedCharArray> innerAlone = scene.Pixels();
  scene.Show(-1);
  int compared = 0, worst = 0;
  for (vtkIdType i = 0; i < group->GetNumberOfValues(); i += 3)
  {
    bool innerAbsent = true;
    for (int c = 0; c < 3; ++c)
    {
      innerAbsent = innerAbsent && innerAlone->GetValue(i + c) == background->GetValue(i + c);
    }
    if (innerAbsent)
    {
      ++compared;
      for (int c = 0; c < 3; ++c)
      {
        worst =
          std::max(worst, std::abs(int(group->GetValue(i + c)) - int(outerAlone->GetValue(i + c))));
      }
    }
  }
  std::cout << "mesh inside a mesh: " << compared
            << " pixels without the inner mesh, largest difference to the outer mesh alone "
            << worst << "/255\n";
  ok =
    Expect(worst == 0, "mesh inside a mesh: the outer mesh alone where the inner is absent") && ok;
  return ok;
}

// The camera inside both of two overlapping cubes.
bool TestCameraInside(vtkUnstructuredGrid* box)
{
  Scene scene(128);
  scene.Add(box, trctest::MakePropertyFor(box, 0.2));

  scene.AddPlaced(box, OtherProperty(box, 0.3), box, 0.9, { 0.1, 0.05, 0.0 }, { 10, 0, 30 });
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->SetPosition(0.55, 0.5, 0.45);
  camera->SetFocalPoint(1.55, 0.8, 0.6);
  camera->SetViewUp(0, 0, 1);
  camera->SetViewAngle(70);
  camera->SetClippingRange(0.01, 10);
  return CheckGroup(scene, "camera inside both");
}

// Two volumes that do not overlap: each drawn alone, the same pixels as each alone.
bool TestApart(vtkUnstructuredGrid* torus, vtkUnstructuredGrid* spx)
{
  Scene scene(128);
  scene.Add(torus, trctest::MakePropertyFor(torus, 0.08));
  vtkVolume* second =
    scene.AddPlaced(spx, OtherProperty(spx, 0.1), torus, 0.7, { 1.2, 0.0, 0.0 }, { 0, 0, 0 });
  scene.Renderer->ResetCamera();
  bool ok = CheckScene(scene, trctest::Bounds(), "apart");
  for (auto& mapper : scene.Mappers)
  {
    ok = Expect(mapper->GetStatistics()->GetNumberOfGroupedVolumes() == 1, "apart: no group") && ok;
  }
  vtkSmartPointer<vtkUnsignedCharArray> both = scene.Pixels();
  scene.Show(0);
  scene.Window->Render();
  vtkSmartPointer<vtkUnsignedCharArray> first = scene.Pixels();
  scene.Show(1);
  scene.Window->Render();
  vtkSmartPointer<vtkUnsignedCharArray> other = scene.Pixels();
  scene.Show(-1);
  // They cover different pixels: each pixel of both is the first's or the second's.
  int worst = 0;
  for (vtkIdType i = 0; i < both->GetNumberOfValues(); i += 3)
  {
    bool asFirst = true;
    bool asOther = true;
    for (int c = 0; c < 3; ++c)
    {
      asFirst = asFirst && both->GetValue(i + c) == first->GetValue(i + c);
      asOther = asOther && both->GetValue(i + c) == other->GetValue(i + c);
    }
    if (!asFirst && !asOther)
    {
      for (int c = 0; c < 3; ++c)
      {
        worst = std::max(worst, std::abs(int(both->GetValue(i + c)) - int(first->GetValue(i + c))));
      }
    }
  }
  std::cout << "apart: largest difference to the volumes drawn each alone " << worst << "/255\n";
  ok = Expect(worst == 0, "apart: the same pixels as each volume alone") && ok;
  ok = Expect(GroupWarnings(scene.Warnings) == 0, "apart: no warning") && ok;
  return ok;
}

// Overlapping copies of a mesh, each turned, scaled and shifted and with its own transfer
// function (copy i of AddCopies).
void AddCopies(Scene& scene, vtkUnstructuredGrid* spx, int count)
{
  for (int i = 0; i < count; ++i)
  {
    scene.AddPlaced(spx,
      i % 2 == 0 ? trctest::MakePropertyFor(spx, 0.1 + 0.05 * i)
                 : OtherProperty(spx, 0.1 + 0.05 * i),
      spx, 1.0 - 0.06 * i, { 0.06 * i, -0.03 * i, 0.02 * i }, { 15.0 * i, 25.0 * i, -10.0 * i });
  }
  scene.Renderer->ResetCamera();
  scene.Renderer->GetActiveCamera()->Elevation(-20);
  scene.Renderer->ResetCameraClippingRange();
}

// Four overlapping copies: one traversal of four. Eight: one traversal takes as many as the
// compute shader's texture units hold (seven of these on llvmpipe and on an H100, whose compute
// shaders read 32), the others are drawn alone, each warned once; as many as fit, alone in a
// scene, are one traversal within the bounds of the exact reference.
bool TestMany(vtkUnstructuredGrid* spx)
{
  // Three copies: the fewest that share one copy of their code.
  Scene three(128);
  AddCopies(three, spx, 3);
  bool ok = CheckGroup(three, "three overlapping", 1);
  Scene four(128);
  AddCopies(four, spx, 4);
  ok = CheckGroup(four, "four overlapping", 1) && ok;
  // One of four with cell scalars: their code differs, a copy per volume.
  Scene mixed(128);
  AddCopies(mixed, spx, 3);
  mixed.AddPlaced(trctest::WithCellScalars(spx, false), OtherProperty(spx, 0.25), spx, 0.82,
    { 0.18, -0.09, 0.06 }, { 45.0, 75.0, -30.0 });
  mixed.Renderer->ResetCamera();
  mixed.Renderer->ResetCameraClippingRange();
  ok = CheckGroup(mixed, "four overlapping, one of cell scalars", 0) && ok;

  Scene eight(128);
  AddCopies(eight, spx, 8);
  eight.Window->Render();
  const int taken = eight.Mappers[0]->GetStatistics()->GetNumberOfGroupedVolumes();
  std::cout << "eight overlapping: " << taken << " in one traversal\n";
  ok = Expect(taken >= 5 && taken <= 8, "eight overlapping: five or more in one traversal") && ok;
  for (int i = 0; i < 8; ++i)
  {
    vtkTiledRayCastStatistics* stats = eight.Mappers[i]->GetStatistics();
    ok =
      Expect(stats->GetRendered() && stats->GetNumberOfGroupedVolumes() == (i < taken ? taken : 1),
        "eight overlapping: the first in one traversal, the others alone") &&
      ok;
  }
  if (!Expect(GroupWarnings(eight.Warnings) == 8 - taken,
        "eight overlapping: one warning per volume left out"))
  {
    std::cerr << eight.Warnings->Text << "\n";
    ok = false;
  }
  eight.Window->Render();
  ok = Expect(GroupWarnings(eight.Warnings) == 8 - taken, "eight overlapping: warned once") && ok;
  if (taken > 4)
  {
    Scene fit(128);
    AddCopies(fit, spx, taken);
    ok = CheckGroup(fit, std::to_string(taken) + " overlapping", 1) && ok;
  }
  return ok;
}

// Optically thick media overlapping (optical depth up to about 40 across): the mixture's
// panels and early ray termination.
bool TestThick(vtkUnstructuredGrid* box)
{
  Scene scene(96);
  scene.Add(box, trctest::MakePropertyFor(box, 0.02));

  scene.AddPlaced(box, OtherProperty(box, 0.015), box, 0.8, { 0.15, 0.1, 0.05 }, { 30, 20, 10 });
  scene.Renderer->ResetCamera();
  scene.Renderer->GetActiveCamera()->Azimuth(20);
  scene.Renderer->ResetCameraClippingRange();
  bool ok = CheckGroup(scene, "thick overlapping");

  // Both of cell scalars: where they overlap the medium is constant per piece, integrated in
  // closed form (trcCompositeMixture) rather than in panels.
  vtkNew<vtkPointDataToCellData> toCells;
  toCells->SetInputData(box);
  toCells->Update();
  vtkUnstructuredGrid* cells = vtkUnstructuredGrid::SafeDownCast(toCells->GetOutput());
  cells->GetPointData()->Initialize();
  for (auto& mapper : scene.Mappers)
  {
    mapper->SetInputData(cells);
  }
  ok = CheckGroup(scene, "thick overlapping, cell scalars") && ok;
  return ok;
}

// Empty-space skipping (a band of one volume's scalars: rays enter and leave its visible part)
// overlapping a volume of cell scalars: each volume's own shader variants in one traversal.
bool TestBandAndCells(vtkUnstructuredGrid* fin, vtkUnstructuredGrid* spx)
{
  Scene scene(96);
  double range[2];
  fin->GetPointData()->GetScalars()->GetRange(range);
  scene.Add(fin, trcscene::MakeBandProperty(range, 0.5, 0.1, fin->GetLength() / 20));
  vtkSmartPointer<vtkUnstructuredGrid> cells = trctest::WithCellScalars(spx, false);
  // The cells keep spx's points: placed as spx.
  scene.AddPlaced(cells, OtherProperty(spx, 0.1), fin, 0.9, { 0.0, 0.05, 0.0 }, { 0, 30, 0 });
  scene.Renderer->ResetCamera();
  scene.Renderer->GetActiveCamera()->Azimuth(-40);
  scene.Renderer->ResetCameraClippingRange();
  bool ok = CheckGroup(scene, "band and cell scalars");
  ok = Expect(scene.Mappers[0]->GetStatistics()->GetNumberOfVisibleTetrahedra() <
           fin->GetNumberOfCells(),
         "band and cell scalars: empty space skipped") &&
    ok;
  return ok;
}

// The GLSL a frame composed, over every mapper of the scene (the one that drew the group counts
// its programs).
int Compositions(Scene& scene)
{
  int count = 0;
  for (auto& mapper : scene.Mappers)
  {
    count += mapper->GetStatistics()->GetNumberOfShaderCompositions();
  }
  return count;
}

// The group's programs are composed only when what decides them changes: not on a steady frame
// (the camera turns), again when a volume's transfer function makes it skip empty space (its
// own shader variant, TRC_SKIP_EMPTY_SPACE) and when a volume joins the group.
bool TestSteadyGroup(vtkUnstructuredGrid* spx)
{
  Scene scene(64);
  scene.Add(spx, trctest::MakePropertyFor(spx, 0.1));
  const std::array<double, 3> orientation = { 0, 30, 0 };
  vtkVolume* second =
    scene.AddPlaced(spx, OtherProperty(spx, 0.1), spx, 0.8, { 0.1, 0.0, 0.0 }, orientation);
  scene.Renderer->ResetCamera();
  auto grouped = [&scene](int volumes)
  {
    bool all = true;
    for (auto& mapper : scene.Mappers)
    {
      all = all && mapper->GetStatistics()->GetNumberOfGroupedVolumes() == volumes;
    }
    return all;
  };
  auto frame = [&scene]()
  {
    scene.Renderer->GetActiveCamera()->Azimuth(3);
    scene.Window->Render();
    return Compositions(scene);
  };
  bool ok = Expect(frame() >= 1 && grouped(2), "steady group: the first frame composes");
  ok = Expect(frame() == 0 && grouped(2), "steady group: a steady frame composes nothing") && ok;
  ok = Expect(frame() == 0 && grouped(2), "steady group: nor the next") && ok;

  double range[2];
  spx->GetPointData()->GetScalars()->GetRange(range);
  second->SetProperty(trcscene::MakeBandProperty(range, 0.5, 0.2, spx->GetLength() / 10));
  ok =
    Expect(frame() >= 1 && grouped(2) &&
        scene.Mappers[1]->GetStatistics()->GetNumberOfVisibleTetrahedra() < spx->GetNumberOfCells(),
      "steady group: a transfer function that skips empty space composes again") &&
    ok;
  ok = Expect(frame() == 0 && grouped(2), "steady group: then nothing") && ok;

  scene.AddPlaced(
    spx, trctest::MakePropertyFor(spx, 0.2), spx, 0.9, { -0.1, 0.05, 0.0 }, orientation);
  ok = Expect(frame() >= 1 && grouped(3), "steady group: a third volume composes again") && ok;
  ok = Expect(frame() == 0 && grouped(3), "steady group: then nothing") && ok;
  // The programs kept are the right ones: the scene against the reference.
  // One of them skips empty space (its own shader variant): a copy of the code per volume.
  ok = CheckGroup(scene, "steady group, three volumes", 0) && ok;

  // Volumes of other programs than the first's clip their entries by the scene's depth too. Once
  // they read an inactive unit (their own scene depth): right by chance until another mapper
  // left a texture there.
  for (size_t i = 0; i < scene.Volumes.size(); ++i)
  {
    vtkNew<vtkProjectedTetrahedraMapper> projected;
    projected->SetInputData(scene.Mappers[i]->GetInput());
    scene.Volumes[i]->SetMapper(projected);
  }
  scene.Window->Render();
  for (size_t i = 0; i < scene.Volumes.size(); ++i)
  {
    scene.Volumes[i]->SetMapper(scene.Mappers[i]);
  }
  ok = CheckGroup(scene, "steady group, after VTK's projected tetrahedra drew its volumes") && ok;
  auto ball = trctest::MakeBall(second->GetCenter(), 0.1 * spx->GetLength(), 24);
  scene.Renderer->AddActor(ball);
  ok = CheckGroup(scene, "steady group, an opaque sphere") && ok;
  return ok;
}

// One mapper for two overlapping volumes (VTK allows it): the mapper holds one frame's state,
// so they are drawn one by one as before, with one warning.
bool TestSharedMapper(vtkUnstructuredGrid* spx)
{
  Scene scene(64);
  scene.Add(spx, trctest::MakePropertyFor(spx, 0.1));
  auto second = vtkSmartPointer<vtkVolume>::New();
  second->SetMapper(scene.Mappers[0]);
  second->SetProperty(OtherProperty(spx, 0.1));
  Place(second, spx, spx, 0.8, { 0.1, 0.0, 0.0 }, { 0, 30, 0 });
  scene.Renderer->AddVolume(second);
  scene.Renderer->ResetCamera();
  scene.Window->Render();
  scene.Window->Render();
  bool ok = Expect(scene.Mappers[0]->GetStatistics()->GetRendered() &&
      scene.Mappers[0]->GetStatistics()->GetNumberOfGroupedVolumes() == 1,
    "shared mapper: no group");
  ok = Expect(GroupWarnings(scene.Warnings) == 1, "shared mapper: one warning") && ok;
  return ok;
}
}

int TestTiledRayCastOverlapping(int argc, char* argv[])
{
  vtkSmartPointer<vtkUnstructuredGrid> torus = trctest::ReadMesh(argc, argv, "torus_vistrails.vtu");
  vtkSmartPointer<vtkUnstructuredGrid> spx = trctest::ReadMesh(argc, argv, "spx_vistrails.vtu");
  vtkSmartPointer<vtkUnstructuredGrid> box = trctest::ReadMesh(argc, argv, "box5_tets.vtu");
  vtkSmartPointer<vtkUnstructuredGrid> fin = trctest::ReadMesh(argc, argv, "bluntfin_tets.vtu");
  if (!torus || !spx || !box || !fin)
  {
    return EXIT_FAILURE;
  }
  if (!trctest::RenderingSupported())
  {
    return VTK_SKIP_RETURN_CODE;
  }
  bool ok = TestTwo(torus, spx);
  ok = TestInside(spx, spx) && ok;
  ok = TestCameraInside(box) && ok;
  ok = TestApart(torus, spx) && ok;
  ok = TestMany(spx) && ok;
  ok = TestThick(box) && ok;
  ok = TestBandAndCells(fin, spx) && ok;
  ok = TestSharedMapper(spx) && ok;
  ok = TestSteadyGroup(spx) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
