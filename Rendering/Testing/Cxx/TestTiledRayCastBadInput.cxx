/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTiledRayCastBadInput.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Bad input gets a clear error, nothing is drawn for the volume, nothing crashes, and the rest
// of the scene (an opaque cone) still renders: an empty grid, a grid without scalars, a grid of
// triangles only, a mesh larger than the texture limits, a blend mode the mapper does not do.
// NaN scalars are not an error: the tetrahedra touching them are transparent, as the exact
// reference renderer has them. Degenerate tetrahedra are warned about unless
// WarnAboutDegenerateCells is off. A mapper whose input is removed after a good frame says it drew
// nothing in the next one (vtkVolume never calls its Render() without an input).
#include "TiledRayCastTestScene.h"

#include "vtkActor.h"
#include "vtkAppendFilter.h"
#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkConeSource.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkTetMeshValidationReport.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <functional>
#include <limits>

namespace
{
using trctest::Expect;
using trctest::MessageCounter;
// Renders `grid` next to an opaque cone and checks that the mapper refused it with an error
// containing `message`, drew nothing, and left the cone on screen.
bool Refused(const std::string& label, vtkUnstructuredGrid* grid, const char* message,
  const std::function<void(vtkTiledRayCastVolumeMapper*)>& configure = nullptr)
{
  vtkNew<vtkTiledRayCastVolumeMapper> mapper;
  mapper->SetInputData(grid);
  if (configure)
  {
    configure(mapper);
  }
  vtkNew<MessageCounter> errors;
  mapper->AddObserver(vtkCommand::ErrorEvent, errors);
  mapper->AddObserver(vtkCommand::WarningEvent, errors);

  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(trctest::MakeProperty(0, 1, 0.1));
  vtkNew<vtkConeSource> cone;
  vtkNew<vtkPolyDataMapper> coneMapper;
  coneMapper->SetInputConnection(cone->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(coneMapper);
  actor->GetProperty()->SetColor(1, 1, 1);
  actor->GetProperty()->SetAmbient(1);
  actor->GetProperty()->SetDiffuse(0);

  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0, 0, 0);
  renderer->AddActor(actor);
  renderer->AddVolume(volume);
  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(64, 64);
  window->AddRenderer(renderer);
  cone->Update();
  renderer->ResetCamera(cone->GetOutput()->GetBounds());
  window->Render();
  window->Render(); // a second frame must neither crash nor repeat the error

  bool ok = Expect(errors->Count > 0, label + ": an error was reported");
  const std::string text = errors->Text;
  ok = Expect(text.find(message) != std::string::npos,
         label + ": the message says '" + message + "' (got: " + text + ")") &&
    ok;
  ok = Expect(errors->Count <= 2, label + ": reported once per cause, not every frame") && ok;
  ok = Expect(!mapper->GetStatistics()->GetRendered(), label + ": nothing drawn") && ok;
  unsigned char* center = window->GetPixelData(32, 32, 32, 32, 0);
  ok = Expect(center[0] > 200, label + ": the cone still renders") && ok;
  delete[] center;
  std::cout << label << ": " << text << "\n";
  return ok;
}

vtkSmartPointer<vtkUnstructuredGrid> OneTet(bool withScalars)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  points->InsertNextPoint(0, 0, 1);
  grid->SetPoints(points);
  const vtkIdType ids[4] = { 0, 1, 2, 3 };
  grid->InsertNextCell(VTK_TETRA, 4, ids);
  if (withScalars)
  {
    vtkNew<vtkDoubleArray> s;
    s->SetName("s");
    for (int i = 0; i < 4; ++i)
    {
      s->InsertNextValue(0.25 * i);
    }
    grid->GetPointData()->SetScalars(s);
  }
  return grid;
}

// One triangle, with scalars: no 3D cell.
vtkSmartPointer<vtkUnstructuredGrid> Triangles()
{
  auto triangles = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  triangles->SetPoints(points);
  const vtkIdType ids[3] = { 0, 1, 2 };
  triangles->InsertNextCell(VTK_TRIANGLE, 3, ids);
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  s->SetNumberOfValues(3);
  s->FillValue(0.5);
  triangles->GetPointData()->SetScalars(s);
  return triangles;
}

// Refused inputs and settings, each in a window of its own.
bool RefusedInputs(vtkUnstructuredGrid* spx)
{
  vtkNew<vtkUnstructuredGrid> empty;
  bool ok = Refused("empty grid", empty, "Cannot render");
  // Every tetrahedron of zero volume (spx flattened onto z = 0): nothing to draw, as the
  // reference says too (151 pixels were drawn).
  vtkNew<vtkUnstructuredGrid> flat;
  flat->DeepCopy(spx);
  vtkNew<vtkPoints> flatPoints;
  flatPoints->DeepCopy(spx->GetPoints());
  for (vtkIdType p = 0; p < flatPoints->GetNumberOfPoints(); ++p)
  {
    double x[3];
    flatPoints->GetPoint(p, x);
    flatPoints->SetPoint(p, x[0], x[1], 0.0);
  }
  flat->SetPoints(flatPoints);
  ok = Refused("every tetrahedron flat", flat, "zero volume") && ok;
  ok = Refused("no scalars", OneTet(false), "scalar") && ok;
  ok = Refused("triangles only", Triangles(), "3D") && ok;
  using Setting = std::function<void(vtkTiledRayCastVolumeMapper*)>;
  const struct
  {
    const char* Label;
    const char* Message;
    Setting Configure;
  } settings[] = {
    { "too large", "texture buffer",
      [](vtkTiledRayCastVolumeMapper* m) { m->SetMaximumTextureBufferSize(1000); } },
    { "too large (paper)", "texture",
      [](vtkTiledRayCastVolumeMapper* m)
      {
        m->SetMeshLayoutToPaper();
        m->SetMaximumTextureSize(64);
      } },
    { "isosurface blend mode", "not supported",
      [](vtkTiledRayCastVolumeMapper* m) { m->SetBlendMode(5); } },
    { "maximum intensity, fragment pipeline", "compute pipeline",
      [](vtkTiledRayCastVolumeMapper* m)
      {
        m->SetBlendModeToMaximumIntensity();
        m->SetPipelineToFragment();
      } },
  };
  for (const auto& setting : settings)
  {
    ok = Refused(setting.Label, spx, setting.Message, setting.Configure) && ok;
  }
  return ok;
}

// More than MaximumGPUMemory: refused before the build where the input's counts tell (the builder
// never runs: no progress strictly between 0 and 1, which only the build reports; the pipeline
// reports 0 and 1 around every update), once the layout is packed otherwise, the sizes named.
// spx: 12936 tetrahedra and 2896 points, 32 x 12936 + 16 x 2896 = 460288 bytes in the compact
// layout, and 12936 / 8 + 4 x 2760 more for the visible set and the entry faces.
bool GPUMemoryRefused(vtkUnstructuredGrid* spx)
{
  int progressEvents = 0;
  vtkNew<vtkCallbackCommand> progress;
  progress->SetClientData(&progressEvents);
  progress->SetCallback(
    [](vtkObject*, unsigned long, void* count, void* data)
    {
      const double value = *static_cast<double*>(data);
      *static_cast<int*>(count) += value > 0.0 && value < 1.0 ? 1 : 0;
    });
  const struct
  {
    const char* Label;
    vtkIdType Limit;
    const char* Message;
    bool Built;
  } cases[] = {
    { "GPU memory, known before the build", 100000, "known before the build", false },
    { "GPU memory, known from the layout", 460289, "needs 473 kB on the GPU (472945 bytes), more than the 460 kB", true },
  };
  bool ok = true;
  for (const auto& c : cases)
  {
    progressEvents = 0;
    ok = Refused(c.Label, spx, c.Message,
           [&](vtkTiledRayCastVolumeMapper* m)
           {
             m->SetMaximumGPUMemory(c.Limit);
             m->AddObserver(vtkCommand::ProgressEvent, progress);
           }) &&
      ok;
    ok = Expect((progressEvents > 0) == c.Built,
           std::string(c.Label) + (c.Built ? ": built" : ": not built")) &&
      ok;
  }
  return ok;
}

// Seven clipping planes: the first six clip (as in VTK's OpenGL mappers), and the error says
// so once.
bool SevenClippingPlanes(vtkUnstructuredGrid* spx)
{
  bool ok = true;
  trctest::WatchedVolume scene(spx, trctest::MakePropertyFor(spx, 0.1), 64);
  MessageCounter* errors = scene.CountErrors();
  double b[6];
  spx->GetBounds(b);
  for (int k = 0; k < 7; ++k)
  {
    vtkNew<vtkPlane> plane; // each keeps the whole mesh
    plane->SetOrigin(b[0] - 1.0, b[2] - 1.0, b[4] - 1.0);
    plane->SetNormal(1.0, 0.5 * k, 0.25);
    scene.Mapper->AddClippingPlane(plane);
  }
  scene.Window->Render();
  scene.Window->Render();
  ok = Expect(errors->Count == 1 && errors->Text.find("first 6") != std::string::npos,
         "seven clipping planes: one error naming the six used (got: " + errors->Text + ")") &&
    ok;
  ok = Expect(scene.Mapper->GetStatistics()->GetRendered(), "seven clipping planes: drawn") && ok;
  return ok;
}

// Shading and gradient opacity are drawn, silently, except for what they do not do as asked:
// a gradient opacity of curved intervals (midpoint, sharpness) is sampled, a positional light
// is lit as a directional one (said once each). A gradient opacity of 1 everywhere (as
// ParaView sets) changes nothing and says nothing.
bool ShadingWarnings(vtkUnstructuredGrid* spx)
{
  bool ok = true;
  auto property = trctest::MakePropertyFor(spx, 0.1);
  vtkNew<vtkPiecewiseFunction> one;
  one->AddPoint(0.0, 1.0);
  one->AddPoint(100.0, 1.0);
  property->SetGradientOpacity(one);
  trctest::WatchedVolume scene(spx, property, 64);
  scene.Window->Render();
  ok = Expect(scene.Warnings->Count == 0,
         "a gradient opacity of 1: no warning (got: " + scene.Warnings->Text + ")") &&
    ok;
  property->ShadeOn();
  scene.Window->Render();
  ok =
    Expect(scene.Warnings->Count == 0, "shading: no warning (got: " + scene.Warnings->Text + ")") &&
    ok;
  vtkNew<vtkPiecewiseFunction> ramp;
  ramp->AddPoint(0.0, 0.0);
  ramp->AddPoint(100.0, 1.0);
  property->SetGradientOpacity(ramp);
  scene.Window->Render();
  ok = Expect(scene.Warnings->Count == 0,
         "gradient opacity: no warning (got: " + scene.Warnings->Text + ")") &&
    ok;
  ramp->AddPoint(0.0, 0.0, 0.3, 0.5);
  scene.Window->Render();
  scene.Window->Render();
  ok =
    Expect(scene.Warnings->Count == 1 && scene.Warnings->Text.find("sampled") != std::string::npos,
      "a curved gradient opacity: one warning (got: " + scene.Warnings->Text + ")") &&
    ok;
  vtkNew<vtkLight> spot;
  spot->PositionalOn();
  spot->SetPosition(0.0, 0.0, 50.0);
  scene.Renderer->AddLight(spot);
  scene.Window->Render();
  scene.Window->Render();
  ok = Expect(scene.Warnings->Count == 2 &&
           scene.Warnings->Text.find("directional") != std::string::npos,
         "a positional light: one warning (got: " + scene.Warnings->Text + ")") &&
    ok;
  ok = Expect(scene.Mapper->GetStatistics()->GetRendered(), "shaded: drawn") && ok;
  return ok;
}

// Depth peeling for volumes in the fragment pipeline: VTK's dual depth peeling hands volumes
// depth ranges through shader replacements written for its image ray caster; the compute
// pipeline takes part (TestTiledRayCastTranslucent), the fragment pipeline cannot (it drew
// tile-patterned garbage in the peels). It draws the volume after the renderer has finished,
// as without the switch: the same image as with peeling for volumes off, and one warning.
bool VolumetricPeeling(vtkUnstructuredGrid* spx)
{
  bool ok = true;
  trctest::WatchedVolume scene(spx, trctest::MakePropertyFor(spx, 0.1), 64);
  scene.Mapper->SetPipelineToFragment();
  MessageCounter* errors = scene.CountErrors();
  double centre[3];
  spx->GetCenter(centre);
  auto translucent = trctest::MakeBall(centre, 0.3 * spx->GetLength());
  translucent->GetProperty()->SetOpacity(0.4);
  scene.Renderer->AddActor(translucent);
  scene.Renderer->SetUseDepthPeeling(1);
  auto pixels = [&](vtkUnsignedCharArray* out)
  {
    scene.Window->Render();
    scene.Window->Render();
    scene.Window->GetPixelData(0, 0, 63, 63, 0, out, 0);
  };
  vtkNew<vtkUnsignedCharArray> without;
  pixels(without);
  scene.Renderer->SetUseDepthPeelingForVolumes(1);
  vtkNew<vtkUnsignedCharArray> with;
  pixels(with);
  int differing = 0;
  for (vtkIdType i = 0; i < with->GetNumberOfValues(); ++i)
  {
    differing += std::abs(with->GetValue(i) - without->GetValue(i)) > 1 ? 1 : 0;
  }
  ok = Expect(errors->Count == 0 && scene.Warnings->Count == 1,
         "volumetric peeling: no error, one warning (got: " + errors->Text + scene.Warnings->Text +
           ")") &&
    ok;
  ok = Expect(differing == 0,
         "volumetric peeling: the image of peeling for volumes off (" + std::to_string(differing) +
           " values differ)") &&
    ok;
  ok = Expect(scene.Mapper->GetStatistics()->GetRendered() &&
           scene.Mapper->GetStatistics()->GetNumberOfRays() > 100 &&
           scene.Mapper->GetStatistics()->GetDepthPeelingStage() == 0,
         "volumetric peeling: the volume drawn, after the peeling") &&
    ok;
  return ok;
}

// No input after a good frame: VTK's pipeline reports the missing input (on the mapper's
// executive) and the statistics describe the empty frame, not the last one drawn.
bool NoInputAfterFrame(vtkUnstructuredGrid* spx)
{
  bool ok = true;
  trctest::WatchedVolume scene(spx, trctest::MakePropertyFor(spx, 0.1), 64);
  scene.Window->Render();
  ok =
    Expect(scene.Mapper->GetStatistics()->GetRendered(), "no input: the first frame renders") && ok;
  vtkNew<MessageCounter> pipelineErrors;
  scene.Mapper->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, pipelineErrors);
  scene.Mapper->RemoveAllInputConnections(0);
  scene.Window->Render();
  ok = Expect(pipelineErrors->Count > 0, "no input: the pipeline reports it") && ok;
  ok = Expect(!scene.Mapper->GetStatistics()->GetRendered(),
         "no input: the statistics say nothing was rendered") &&
    ok;
  ok = Expect(scene.Mapper->GetStatistics()->GetNumberOfRays() == 0, "no input: no rays") && ok;
  return ok;
}

// NaN scalars: a warning from the builder, and the image of the exact reference (which also
// makes the tetrahedra that touch them transparent).
bool NaNScalars(vtkUnstructuredGrid* spx)
{
  bool ok = true;
  vtkNew<vtkUnstructuredGrid> grid;
  grid->DeepCopy(spx);
  vtkDataArray* s = grid->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < s->GetNumberOfTuples(); i += 7)
  {
    s->SetComponent(i, 0, std::numeric_limits<double>::quiet_NaN());
  }
  s->Modified();
  double range[2];
  spx->GetPointData()->GetScalars()->GetRange(range);
  trctest::WatchedVolume scene(
    grid, trctest::MakeProperty(range[0], range[1], 0.1 * grid->GetLength()), 96);
  scene.Window->Render();
  ok = Expect(scene.Mapper->GetValidationReport()->GetNumberOfNonFiniteScalars() > 0,
         "NaN scalars are counted") &&
    ok;
  ok =
    Expect(scene.Warnings->Text.find("NaN") != std::string::npos, "NaN scalars are reported") && ok;
  ok =
    Expect(scene.Mapper->GetStatistics()->GetRendered(), "a mesh with NaN scalars renders") && ok;
  ok = trctest::CheckAgainstReference(
         scene.Window, scene.Renderer, scene.Volume, trctest::Bounds(), "NaN") &&
    ok;
  return ok;
}

// Degenerate (zero-volume) tetrahedra: spx with one more, flat, beside it. Warned about by
// default; with WarnAboutDegenerateCells off (what ParaView's plugin sets for the pieces it cuts
// at the ranks' planes, which have them wherever a plane grazes a point) counted, not warned
// about. Both frames render spx exactly.
bool DegenerateCells(vtkUnstructuredGrid* spx)
{
  bool ok = true;
  vtkNew<vtkUnstructuredGrid> grid;
  grid->DeepCopy(spx);
  double bounds[6];
  spx->GetBounds(bounds);
  vtkPoints* points = grid->GetPoints();
  const double z = bounds[5] + 0.5 * (bounds[5] - bounds[4]);
  vtkIdType flat[4];
  for (int i = 0; i < 4; ++i)
  {
    // Four points of one plane, over the mesh: a tetrahedron of zero volume.
    flat[i] = points->InsertNextPoint(bounds[i % 2], bounds[2 + i / 2], z);
    grid->GetPointData()->GetScalars()->InsertNextTuple1(
      grid->GetPointData()->GetScalars()->GetComponent(0, 0));
  }
  grid->InsertNextCell(VTK_TETRA, 4, flat);
  double range[2];
  spx->GetPointData()->GetScalars()->GetRange(range);
  for (bool warn : { true, false })
  {
    trctest::WatchedVolume scene(
      grid, trctest::MakeProperty(range[0], range[1], 0.1 * grid->GetLength()), 96);
    scene.Mapper->SetWarnAboutDegenerateCells(warn);
    scene.Window->Render();
    const std::string label = warn ? "degenerate, warned" : "degenerate, not warned";
    ok = Expect(scene.Mapper->GetValidationReport()->GetNumberOfDegenerateTetrahedra() == 1,
           label + ": counted") &&
      ok;
    ok = Expect(warn ? scene.Warnings->Count == 1 &&
               scene.Warnings->Text.find("degenerate") != std::string::npos
                     : scene.Warnings->Count == 0,
           label + ": " + (warn ? "one warning" : "no warning") + " (got: " + scene.Warnings->Text +
             ")") &&
      ok;
    ok = trctest::CheckAgainstReference(
           scene.Window, scene.Renderer, scene.Volume, trctest::Bounds(), label.c_str()) &&
      ok;
  }
  return ok;
}

// Normal service is not a warning: spx with every other tetrahedron inverted (two points
// swapped: the builder reorients them), and a grid of hexahedra, split into tetrahedra. Both
// render silently; the report counts what was done.
bool NormalService(vtkUnstructuredGrid* spx)
{
  bool ok = true;
  vtkNew<vtkUnstructuredGrid> inverted;
  inverted->DeepCopy(spx);
  for (vtkIdType c = 0; c < inverted->GetNumberOfCells(); c += 2)
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    inverted->GetCellPoints(c, n, ids);
    const vtkIdType swapped[4] = { ids[1], ids[0], ids[2], ids[3] };
    inverted->ReplaceCell(c, 4, swapped);
  }
  vtkNew<vtkImageData> image;
  image->SetDimensions(4, 4, 4);
  vtkNew<vtkFloatArray> values;
  for (vtkIdType i = 0; i < 64; ++i)
  {
    values->InsertNextValue(static_cast<float>(i % 7));
  }
  image->GetPointData()->SetScalars(values);
  vtkNew<vtkAppendFilter> toUnstructured;
  toUnstructured->SetInputData(image);
  toUnstructured->Update();
  vtkUnstructuredGrid* hexahedra = toUnstructured->GetOutput();
  for (vtkUnstructuredGrid* grid : { inverted.Get(), hexahedra })
  {
    if (!grid)
    {
      return false;
    }
    trctest::WatchedVolume scene(grid, trctest::MakePropertyFor(grid, 0.1), 64);
    scene.Window->Render();
    vtkTetMeshValidationReport* report = scene.Mapper->GetValidationReport();
    const bool invertedCase = grid == inverted.Get();
    ok = Expect(invertedCase ? report->GetNumberOfInvertedTetrahedra() > 0
                             : report->GetNumberOfSplitCells() == 27,
           invertedCase ? "inverted tetrahedra are counted" : "27 hexahedra are split") &&
      ok;
    ok = Expect(scene.Warnings->Count == 0,
           std::string(invertedCase ? "reoriented" : "split") +
             " cells render without a warning (" + scene.Warnings->Text + ")") &&
      ok;
    ok = trctest::CheckAgainstReference(scene.Window, scene.Renderer, scene.Volume,
           trctest::Bounds(), invertedCase ? "reoriented" : "split") &&
      ok;
  }
  return ok;
}

// Translucent polygons in the renderer, without depth peeling for volumes, are not composited
// with the volume: one warning, on the first frame only; an opaque actor brings none.
bool TranslucentGeometry(vtkUnstructuredGrid* spx)
{
  bool ok = true;
  for (double opacity : { 1.0, 0.4 })
  {
    trctest::WatchedVolume scene(spx, trctest::MakePropertyFor(spx, 0.1), 64);
    vtkNew<vtkConeSource> cone;
    vtkNew<vtkPolyDataMapper> coneMapper;
    coneMapper->SetInputConnection(cone->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(coneMapper);
    actor->GetProperty()->SetOpacity(opacity);
    scene.Renderer->AddActor(actor);
    scene.Window->Render();
    scene.Window->Render();
    const int expected = opacity < 1.0 ? 1 : 0;
    ok = Expect(scene.Warnings->Count == expected &&
             (expected == 0 || scene.Warnings->Text.find("Translucent") != std::string::npos),
           std::string(expected ? "one warning for translucent geometry"
                                : "no warning for an "
                                  "opaque actor") +
             " (" + scene.Warnings->Text + ")") &&
      ok;
  }
  return ok;
}
} // namespace

int TestTiledRayCastBadInput(int argc, char* argv[])
{
  vtkSmartPointer<vtkUnstructuredGrid> spx = trctest::ReadMesh(argc, argv, "spx_vistrails.vtu");
  if (!spx)
  {
    return EXIT_FAILURE;
  }
  bool ok = true;
  for (auto check :
    { RefusedInputs, GPUMemoryRefused, SevenClippingPlanes, ShadingWarnings, VolumetricPeeling,
      NoInputAfterFrame, NaNScalars, DegenerateCells, NormalService, TranslucentGeometry })
  {
    ok = check(spx) && ok;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
