/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTiledRayCastScenes.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Image tests of vtkTiledRayCastVolumeMapper, one scene per ctest (chosen with --scene):
// each image is compared with the exact reference renderer within stated bounds, then with its
// baseline through VTK's regression test. The reference check is what makes a baseline right;
// the baseline check is what catches a change.
#include "TiledRayCastTestScene.h"

#include "vtkActor.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkDoubleArray.h"
#include "vtkLightKit.h"
#include "vtkOpenGLTiledRayCastVolumeMapper.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPointData.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkTetMeshValidationReport.h"
#include "vtkTiledRayCastStatistics.h"
#include "vtkVolumeMapper.h"
#include "vtkVolumeProperty.h"

#include <cstring>
#include <functional>
#include <map>

namespace
{
using trctest::Expect;
struct Scene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkTiledRayCastVolumeMapper> Mapper;
  vtkSmartPointer<vtkUnstructuredGrid> Grid;
  trctest::Bounds Bounds;
  std::function<bool(Scene&)> Check; // extra assertions after rendering

  bool Load(int argc, char* argv[], const char* file, double fraction = 0.05)
  {
    this->Grid = trctest::ReadMesh(argc, argv, file);
    if (!this->Grid)
    {
      return false;
    }
    this->Mapper->SetInputData(this->Grid);
    // The checks read this frame's counts (the compute pipeline counts on the GPU).
    this->Mapper->SynchronousStatisticsOn();
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(trctest::MakePropertyFor(this->Grid, fraction));
    this->Renderer->AddVolume(this->Volume);
    this->Renderer->SetBackground(0.1, 0.1, 0.15);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(200, 200);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->ResetCamera();
    return true;
  }

  void View(double azimuth, double elevation, double zoom = 1.0)
  {
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->Azimuth(azimuth);
    camera->Elevation(elevation);
    camera->OrthogonalizeViewUp();
    camera->Zoom(zoom);
    this->Renderer->ResetCameraClippingRange();
  }
};

bool RenderedWith(Scene& t, const char* pipeline)
{
  const char* used = t.Mapper->GetStatistics()->GetPipeline();
  return Expect(used && std::string(used) == pipeline, pipeline);
}

// Rendered with `pipeline`, and rays entered the mesh.
bool RaysEnteredWith(Scene& t, const char* pipeline)
{
  return RenderedWith(t, pipeline) &&
    Expect(t.Mapper->GetStatistics()->GetNumberOfRays() > 5000, "rays entered");
}

// Tables interpolate the integral between grid points: looser bounds.
void UseTableBounds(Scene& s)
{
  s.Bounds.RMSE = 1.5;
  s.Bounds.P999 = 8.0;
  s.Bounds.Max = 16.0;
}

// The scene's point scalars averaged to cell scalars, which the mapper renders.
void UseCellScalars(Scene& s)
{
  s.Grid = trctest::WithCellScalars(s.Grid);
  s.Mapper->SetInputData(s.Grid);
  s.Mapper->SetScalarModeToUseCellData();
}

using SceneCheck = std::function<bool(Scene&)>;
using SceneSetup = std::function<bool(Scene&, int, char*[])>;

// A mesh with the default transfer function for its `fraction`, seen from (azimuth, elevation),
// with `check` after rendering.
SceneSetup Seen(
  const char* file, double fraction, double azimuth, double elevation, SceneCheck check = nullptr)
{
  return [=](Scene& s, int argc, char* argv[])
  {
    if (!s.Load(argc, argv, file, fraction))
      return false;
    s.View(azimuth, elevation);
    s.Check = check;
    return true;
  };
}

// `setup` after a mapper setting (pipeline, integration mode, layout).
SceneSetup After(std::function<void(vtkTiledRayCastVolumeMapper*)> setting, SceneSetup setup)
{
  return [=](Scene& s, int argc, char* argv[])
  {
    setting(s.Mapper);
    return setup(s, argc, argv);
  };
}

void Fragment(vtkTiledRayCastVolumeMapper* m)
{
  m->SetPipelineToFragment();
}
void Table2D(vtkTiledRayCastVolumeMapper* m)
{
  m->SetIntegrationModeToPreIntegration2D();
}
void Table3D(vtkTiledRayCastVolumeMapper* m)
{
  m->SetIntegrationModeToPreIntegration3D();
}

// The comb's teeth seen across: rays enter up to 6 times.
bool LoadComb(Scene& s, int argc, char* argv[])
{
  if (!s.Load(argc, argv, "comb6teeth_tetgen_270k.vtu", 0.2))
    return false;
  s.View(90, 10);
  return true;
}

bool CombHasLayers(Scene& t)
{
  return Expect(t.Mapper->GetStatistics()->GetNumberOfLayers() >= 4,
    "rays across the comb's teeth re-enter the mesh several times");
}

// The camera inside a convex mesh: every ray starts in the tet holding its near-plane point.
bool LoadInside(Scene& s, int argc, char* argv[])
{
  if (!s.Load(argc, argv, "cube_sfepy_200k.vtu", 0.1))
    return false;
  vtkCamera* camera = s.Renderer->GetActiveCamera();
  double center[3];
  s.Grid->GetCenter(center);
  camera->SetFocalPoint(center[0] + 1, center[1] + 0.3, center[2] + 0.2);
  camera->SetPosition(center);
  camera->SetViewAngle(60);
  s.Renderer->ResetCameraClippingRange();
  return true;
}

bool AllRaysStartInside(Scene& t)
{
  vtkTiledRayCastStatistics* stats = t.Mapper->GetStatistics();
  return Expect(stats->GetNumberOfNearPlaneRays() == stats->GetNumberOfRays() &&
      stats->GetNumberOfRays() == 200 * 200,
    "every ray starts inside the mesh");
}

// An optically thick slab seen along its 24-unit depth (5 tets, none split by the transfer
// function): scalar 80 to 120 within one piece, colour black to blue, opacity 0 to 0.2 per unit
// length. The exact integral is 119/255 of blue (an independent quadrature gave the same);
// partial pre-integration read its Psi table transposed until a later version and rendered 94,
// and the 2D table's opacity correction, stretched over the whole slab, rendered 148.
// bluntfin under a blend mode other than compositing, against the reference's own evaluation of
// the property's functions (vtkTetReferenceBlending). The average takes the upper 80 % of the
// scalar range only (AverageIPScalarRange); both gray modes get an opacity ramp to 1 and a unit
// distance of a tenth of the mesh's size, so that their images span the gray levels.
bool LoadBlended(Scene& s, int argc, char* argv[], int mode)
{
  if (!s.Load(argc, argv, "bluntfin_tets.vtu", 0.1))
    return false;
  s.Mapper->SetBlendMode(mode);
  double range[2];
  s.Grid->GetPointData()->GetScalars()->GetRange(range);
  s.Mapper->SetAverageIPScalarRange(range[0] + 0.2 * (range[1] - range[0]), range[1]);
  if (mode == vtkVolumeMapper::AVERAGE_INTENSITY_BLEND || mode == vtkVolumeMapper::ADDITIVE_BLEND)
  {
    // Gray images of opacity times the normalised scalar: an opacity ramp to 1 shows them.
    vtkPiecewiseFunction* opacity = s.Volume->GetProperty()->GetScalarOpacity();
    opacity->RemoveAllPoints();
    opacity->AddPoint(range[0], 0.2);
    opacity->AddPoint(range[0] + 0.3 * (range[1] - range[0]), 0.9);
    opacity->AddPoint(range[1], 1.0);
    s.Volume->GetProperty()->SetScalarOpacityUnitDistance(0.1 * s.Grid->GetLength());
  }
  s.View(30, 20);
  s.Check = [](Scene& t) { return RaysEnteredWith(t, "Compute"); };
  return true;
}

// A transformed spx cut by two clipping planes (world coordinates): an oblique one through the
// middle, where rays start inside the mesh, and one that trims a side. Then checks that planes
// which leave nothing of the mesh draw nothing, and that planes which clip nothing change
// nothing.
bool LoadClipped(Scene& s, int argc, char* argv[])
{
  if (!s.Load(argc, argv, "spx_vistrails.vtu", 0.02))
    return false;
  s.Volume->SetOrientation(10, 25, 0);
  s.Volume->SetScale(1.2, 0.8, 1.0);
  s.Renderer->ResetCamera();
  s.View(20, 30, 1.8);
  double bounds[6];
  s.Volume->GetBounds(bounds);
  const double centre[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  vtkNew<vtkPlane> oblique;
  oblique->SetOrigin(centre);
  oblique->SetNormal(0.6, -0.3, 0.75);
  s.Mapper->AddClippingPlane(oblique);
  vtkNew<vtkPlane> side;
  side->SetOrigin(centre[0], bounds[2] + 0.2 * (bounds[3] - bounds[2]), centre[2]);
  side->SetNormal(0.0, 1.0, 0.1);
  s.Mapper->AddClippingPlane(side);
  s.Check = [](Scene& t)
  {
    vtkTiledRayCastStatistics* stats = t.Mapper->GetStatistics();
    const vtkIdType clippedRays = stats->GetNumberOfRays();
    bool ok = Expect(clippedRays > 8000, "rays entered the clipped mesh");
    // A plane that keeps nothing of the mesh's bounds: nothing is visible, nothing is drawn.
    double b[6];
    t.Volume->GetBounds(b);
    vtkNew<vtkPlane> all;
    all->SetOrigin(b[1] + 1.0, b[3] + 1.0, b[5] + 1.0);
    all->SetNormal(1.0, 1.0, 1.0);
    t.Mapper->AddClippingPlane(all);
    t.Window->Render();
    ok = Expect(!stats->GetRendered(), "nothing drawn when the planes keep nothing") && ok;
    t.Mapper->RemoveClippingPlane(all);
    // A plane that keeps all of it changes nothing.
    vtkNew<vtkPlane> none;
    none->SetOrigin(b[0] - 1.0, b[2] - 1.0, b[4] - 1.0);
    none->SetNormal(1.0, 1.0, 1.0);
    t.Mapper->AddClippingPlane(none);
    t.Window->Render();
    ok = Expect(stats->GetNumberOfRays() == clippedRays, "a plane that clips nothing") && ok;
    t.Mapper->RemoveClippingPlane(none);
    t.Window->Render();
    return ok;
  };
  return true;
}

// torus_tetgen_100k in a table integration mode (the table's bounds). With `fraction` 1e-4 of
// its size as unit distance the tets are near-opaque: most rays stop in the first few tets,
// each of an optical depth of tens. The tables once stored alpha, which saturates there: the 3D
// table was 66/255 off at its worst, the 2D table 181.
SceneSetup TorusTable(int mode, double fraction)
{
  return [=](Scene& s, int argc, char* argv[])
  {
    if (!s.Load(argc, argv, "torus_tetgen_100k.vtu", fraction))
      return false;
    s.Mapper->SetIntegrationMode(mode);
    UseTableBounds(s);
    s.View(20, 50);
    return true;
  };
}

bool LoadThick(Scene& s, int mode)
{
  s.Grid = trctest::TetrahedralBox({ 4.0, 4.0, 24.0 }, { -2.0, -2.0, -12.0 },
    [](const double* x) { return 80.0 + 40.0 * (x[2] + 12.0) / 24.0; });
  s.Mapper->SetInputData(s.Grid);
  s.Mapper->SynchronousStatisticsOn();
  s.Mapper->SetIntegrationMode(mode);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(80.0, 0.0, 0.0, 0.0);
  color->AddRGBPoint(120.0, 0.0, 0.0, 1.0);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(80.0, 0.0);
  opacity->AddPoint(120.0, 0.2);
  s.Volume->SetMapper(s.Mapper);
  s.Volume->SetProperty(trcscene::MakeVolumeProperty(color, opacity, 1.0));
  s.Renderer->AddVolume(s.Volume);
  s.Renderer->SetBackground(0, 0, 0);
  s.Window->SetMultiSamples(0);
  s.Window->SetSize(200, 200);
  s.Window->AddRenderer(s.Renderer);
  // Rays enter at z = -12 (scalar 80, transparent) and leave at z = +12 (scalar 120).
  vtkCamera* camera = s.Renderer->GetActiveCamera();
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(0, 0, -40);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(10);
  s.Renderer->ResetCameraClippingRange();
  s.Check = [](Scene& t)
  {
    unsigned char* pixel = t.Window->GetPixelData(100, 100, 100, 100, 0);
    const int blue = pixel[2];
    delete[] pixel;
    std::cout << "thick slab: blue " << blue << "/255 at the centre (exact 119)\n";
    return Expect(std::abs(blue - 119) <= 1, "the thick slab's exact colour, 119/255");
  };
  return true;
}

// Shading (vtkVolumeProperty::ShadeOn) of spx under the renderer's headlight, with a highlight
// strong enough to show: every segment's colour is scaled and offset by its tet's normal, the
// reference computing the same model from the mesh's own points in double.
bool LoadShaded(Scene& s, int argc, char* argv[])
{
  if (!s.Load(argc, argv, "spx_vistrails.vtu", 0.03))
    return false;
  vtkVolumeProperty* property = s.Volume->GetProperty();
  property->ShadeOn();
  property->SetAmbient(0.25);
  property->SetDiffuse(0.7);
  property->SetSpecular(0.5);
  property->SetSpecularPower(20.0);
  s.View(20, 30);
  return true;
}

// Gradient opacity: a ramp over spx's gradient magnitudes (scalar units per world unit: a tenth
// of its tets below 0.03, half below 0.2, nine tenths below 1.5) that hides where the field is
// flat, as gradient opacity is used to bring out boundaries.
bool LoadGradientOpacity(Scene& s, int argc, char* argv[])
{
  if (!s.Load(argc, argv, "spx_vistrails.vtu", 0.03))
    return false;
  vtkNew<vtkPiecewiseFunction> ramp;
  ramp->AddPoint(0.05, 0.0);
  ramp->AddPoint(1.0, 1.0);
  s.Volume->GetProperty()->SetGradientOpacity(ramp);
  s.View(20, 30);
  return true;
}

// Meshes: convexity, boundary layers, cracks, scalars, the paper's layout.
void AddMeshScenes(std::map<std::string, SceneSetup>& scenes)
{
  const std::map<std::string, SceneSetup> more = {
    { "convex",
      Seen("cube_sfepy_200k.vtu", 0.05, 30, 25,
        [](Scene& t)
        {
          return Expect(t.Mapper->GetStatistics()->GetNumberOfLayers() == 1,
            "a convex mesh has one boundary layer");
        }) },
    { "comb",
      [](Scene& s, int argc, char* argv[])
      {
        // An extruded comb with 6 teeth (the default pipeline: compute where there is OpenGL
        // 4.3, as on llvmpipe).
        s.Check = [](Scene& t) { return RenderedWith(t, "Compute") && CombHasLayers(t); };
        return LoadComb(s, argc, argv);
      } },
    { "comb_fragment",
      [](Scene& s, int argc, char* argv[])
      {
        // The same with the paper's fragment pipeline: first hit and depth peeling.
        s.Mapper->SetPipelineToFragment();
        s.Check = [](Scene& t)
        {
          return RenderedWith(t, "Fragment") && CombHasLayers(t) &&
            Expect(t.Mapper->GetStatistics()->GetNumberOfPeelPasses() >= 4, "peel passes ran");
        };
        return LoadComb(s, argc, argv);
      } },
    { "entries",
      [](Scene& s, int argc, char* argv[])
      {
        // Across the comb's teeth, close up: most pixels cross several boundary layers, more
        // entries than the compute pipeline's first list holds (1.25 per pixel), which must
        // grow within the frame and lose nothing.
        if (!s.Load(argc, argv, "comb6teeth_tetgen_270k.vtu", 0.2))
          return false;
        s.View(90, 10, 3.5);
        s.Check = [](Scene& t)
        {
          vtkTiledRayCastStatistics* stats = t.Mapper->GetStatistics();
          return RenderedWith(t, "Compute") &&
            Expect(stats->GetNumberOfEntries() > 200 * 200 * 5 / 4,
              "more entries than the list first held") &&
            Expect(stats->GetNumberOfLayers() >= 4, "several layers");
        };
        return true;
      } },
    { "spx", Seen("spx_vistrails.vtu", 0.1, 20, 30) },
    // A box with a cubic cavity: every ray through the middle leaves and re-enters.
    { "hollow",
      Seen("hollowcube_tetgen_230k.vtu", 0.1, 15, 10,
        [](Scene& t)
        {
          return Expect(t.Mapper->GetStatistics()->GetNumberOfLayers() >= 2,
            "rays through the cavity re-enter");
        }) },
    // Genus 9.
    { "bracket", Seen("bracket_tets.vtu", 0.1, 40, 30) },
    // The LOX post split into 5 tets per hex: its periodic seam is a crack of coincident,
    // unshared faces that rays must cross without losing or doubling anything.
    { "crack",
      Seen("post_tets5_classic.vtu", 0.1, 0, 60,
        [](Scene& t)
        {
          return Expect(t.Mapper->GetValidationReport()->GetNumberOfCrackFaces() > 0,
            "the builder reports the seam's crack faces");
        }) },
    { "cellscalars",
      [](Scene& s, int argc, char* argv[])
      {
        if (!s.Load(argc, argv, "spx_vistrails.vtu", 0.1))
          return false;
        UseCellScalars(s);
        s.View(20, 30);
        return true;
      } },
    { "offset",
      [](Scene& s, int argc, char* argv[])
      {
        // Double scalars far from zero: spx's scalar spread over 1 unit around 1e6, where a
        // float steps by 1/16. The layouts store scalars minus the middle of their range,
        // subtracted in double (vtkTetMesh::GetScalarShift), and the transfer function's nodes
        // likewise: 21/255 RMSE off the exact reference before, rounding now.
        if (!s.Load(argc, argv, "spx_vistrails.vtu", 0.1))
          return false;
        vtkDataArray* original = s.Grid->GetPointData()->GetScalars();
        double range[2];
        original->GetRange(range);
        vtkNew<vtkDoubleArray> offset;
        offset->SetName("offset");
        offset->SetNumberOfTuples(original->GetNumberOfTuples());
        for (vtkIdType i = 0; i < original->GetNumberOfTuples(); ++i)
        {
          offset->SetValue(
            i, 1.0e6 + (original->GetComponent(i, 0) - range[0]) / (range[1] - range[0]));
        }
        vtkNew<vtkUnstructuredGrid> grid;
        grid->ShallowCopy(s.Grid);
        grid->GetPointData()->SetScalars(offset);
        s.Grid = grid;
        s.Mapper->SetInputData(s.Grid);
        s.Volume->SetProperty(trctest::MakePropertyFor(s.Grid, 0.1));
        s.View(20, 30);
        return true;
      } },
    { "paper",
      [](Scene& s, int argc, char* argv[])
      {
        // The paper's data layout and its one-tet-per-pass scheme with Z-update, occlusion
        // queries every 4 passes and 64-pixel tiles.
        if (!s.Load(argc, argv, "spx_vistrails.vtu", 0.1))
          return false;
        s.Mapper->SetPipelineToFragment();
        s.Mapper->SetMeshLayoutToPaper();
        s.Mapper->SetTetsPerPass(1);
        s.Mapper->SetOcclusionQueryInterval(4);
        s.Mapper->SetTileSize(64);
        s.View(20, 30);
        s.Check = [](Scene& t)
        {
          vtkTiledRayCastStatistics* stats = t.Mapper->GetStatistics();
          return Expect(stats->GetMaximumPassesPerTile() > 4, "several passes per tile") &&
            Expect(stats->GetNumberOfZUpdatePasses() > 0, "Z-update passes ran") &&
            Expect(stats->GetMeshBytesPerTetrahedron() >= 144, "144 bytes per tet");
        };
        return true;
      } },
  };
  scenes.insert(more.begin(), more.end());
}

// Cameras inside the mesh, parallel projection, volume matrices (mirrors too), geometry
// in the volume.
void AddViewScenes(std::map<std::string, SceneSetup>& scenes)
{
  const std::map<std::string, SceneSetup> more = {
    { "geometry",
      [](Scene& s, int argc, char* argv[])
      {
        // An opaque sphere inside the volume: rays stop at its surface.
        if (!s.Load(argc, argv, "spx_vistrails.vtu", 0.1))
          return false;
        double center[3];
        s.Grid->GetCenter(center);
        auto actor = trctest::MakeBall(center, 0.15 * s.Grid->GetLength(), 32);
        actor->GetProperty()->SetColor(0.9, 0.9, 0.9);
        s.Renderer->AddActor(actor);
        s.View(20, 30);
        return true;
      } },
    { "inside",
      [](Scene& s, int argc, char* argv[])
      {
        s.Check = AllRaysStartInside;
        return LoadInside(s, argc, argv);
      } },
    { "inside_fragment",
      [](Scene& s, int argc, char* argv[])
      {
        s.Mapper->SetPipelineToFragment();
        s.Check = [](Scene& t) { return RenderedWith(t, "Fragment") && AllRaysStartInside(t); };
        return LoadInside(s, argc, argv);
      } },
    { "parallel",
      [](Scene& s, int argc, char* argv[])
      {
        if (!s.Load(argc, argv, "bluntfin_tets.vtu", 0.1))
          return false;
        s.Renderer->GetActiveCamera()->ParallelProjectionOn();
        s.Renderer->ResetCamera();
        s.View(35, 20);
        return true;
      } },
    { "transformed",
      [](Scene& s, int argc, char* argv[])
      {
        // Position, orientation and a non-uniform scale on the vtkVolume.
        if (!s.Load(argc, argv, "spx_vistrails.vtu", 0.1))
          return false;
        s.Volume->SetPosition(3, -2, 1);
        s.Volume->SetOrientation(20, 35, -10);
        s.Volume->SetScale(1.5, 0.7, 1.0);
        s.Renderer->ResetCamera();
        s.View(20, 30);
        return true;
      } },
    { "mirror",
      [](Scene& s, int argc, char* argv[])
      {
        // A volume matrix with a negative determinant (a mirror in y, and a turn): its front
        // faces wind clockwise on screen. It once drew nothing in either pipeline.
        if (!s.Load(argc, argv, "spx_vistrails.vtu", 0.1))
          return false;
        s.Volume->SetScale(1.0, -1.0, 1.0);
        s.Volume->SetOrientation(0, 30, 0);
        s.Renderer->ResetCamera();
        s.View(20, 30);
        s.Check = [](Scene& t) { return RaysEnteredWith(t, "Compute"); };
        return true;
      } },
    { "mirror_fragment",
      [](Scene& s, int argc, char* argv[])
      {
        // The same in the fragment pipeline, mirrored in z.
        if (!s.Load(argc, argv, "spx_vistrails.vtu", 0.1))
          return false;
        s.Mapper->SetPipelineToFragment();
        s.Volume->SetScale(1.0, 1.0, -1.0);
        s.Renderer->ResetCamera();
        s.View(20, 30);
        s.Check = [](Scene& t) { return RaysEnteredWith(t, "Fragment"); };
        return true;
      } },
  };
  scenes.insert(more.begin(), more.end());
}

// Blend modes and clipping planes.
void AddBlendAndClipScenes(std::map<std::string, SceneSetup>& scenes)
{
  const std::map<std::string, SceneSetup> more = {
    { "maximum",
      [](Scene& s, int argc, char* argv[])
      { return LoadBlended(s, argc, argv, vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND); } },
    { "minimum",
      [](Scene& s, int argc, char* argv[])
      { return LoadBlended(s, argc, argv, vtkVolumeMapper::MINIMUM_INTENSITY_BLEND); } },
    { "average",
      [](Scene& s, int argc, char* argv[])
      { return LoadBlended(s, argc, argv, vtkVolumeMapper::AVERAGE_INTENSITY_BLEND); } },
    { "additive",
      [](Scene& s, int argc, char* argv[])
      { return LoadBlended(s, argc, argv, vtkVolumeMapper::ADDITIVE_BLEND); } },
    { "clipped", LoadClipped },
    { "clipped_fragment", After(Fragment, LoadClipped) },
  };
  scenes.insert(more.begin(), more.end());
}

// The integration modes on optically thick and near-opaque media.
void AddIntegrationScenes(std::map<std::string, SceneSetup>& scenes)
{
  const std::map<std::string, SceneSetup> more = {
    { "thick",
      [](Scene& s, int, char*[])
      { return LoadThick(s, vtkTiledRayCastVolumeMapper::PARTIAL_PRE_INTEGRATION); } },
    { "thick_table2d",
      [](Scene& s, int, char*[])
      {
        // The 2D table splits optically thick segments (vtkTiledRayCastPreIntegration2D.glsl).
        UseTableBounds(s);
        return LoadThick(s, vtkTiledRayCastVolumeMapper::PRE_INTEGRATION_2D);
      } },
    { "table3d", TorusTable(vtkTiledRayCastVolumeMapper::PRE_INTEGRATION_3D, 0.1) },
    { "opaque_table3d", TorusTable(vtkTiledRayCastVolumeMapper::PRE_INTEGRATION_3D, 1e-4) },
    { "opaque_table2d", TorusTable(vtkTiledRayCastVolumeMapper::PRE_INTEGRATION_2D, 1e-4) },
    { "table2d", TorusTable(vtkTiledRayCastVolumeMapper::PRE_INTEGRATION_2D, 0.1) },
  };
  scenes.insert(more.begin(), more.end());
}

// Shading and gradient opacity.
void AddShadingScenes(std::map<std::string, SceneSetup>& scenes)
{
  const std::map<std::string, SceneSetup> more = {
    { "shaded", LoadShaded },
    { "shaded_fragment",
      [](Scene& s, int argc, char* argv[])
      {
        s.Mapper->SetPipelineToFragment();
        s.Check = [](Scene& t) { return RenderedWith(t, "Fragment"); };
        return LoadShaded(s, argc, argv);
      } },
    { "shaded_paper",
      [](Scene& s, int argc, char* argv[])
      {
        // The paper's layout stores each tet's field: the same gradients.
        s.Mapper->SetPipelineToFragment();
        s.Mapper->SetMeshLayoutToPaper();
        return LoadShaded(s, argc, argv);
      } },
    // spx's tets are thin for this transfer function: the tables hold the default bounds.
    { "shaded_table2d", After(Table2D, LoadShaded) },
    { "shaded_table3d", After(Table3D, LoadShaded) },
    { "shaded_cells",
      [](Scene& s, int argc, char* argv[])
      {
        // Cell scalars have no gradient: the ambient term alone (one warning says so).
        if (!LoadShaded(s, argc, argv))
          return false;
        UseCellScalars(s);
        return true;
      } },
    { "shaded_lightkit",
      [](Scene& s, int argc, char* argv[])
      {
        // VTK's light kit (a headlight, key, fill, back lights: camera lights), one-sided
        // lighting, in a volume of non-uniform scale whose normals need the inverse transpose.
        if (!LoadShaded(s, argc, argv))
          return false;
        s.Volume->SetOrientation(20, 35, -10);
        s.Volume->SetScale(1.5, 0.7, 1.0);
        vtkNew<vtkLightKit> kit;
        kit->AddLightsToRenderer(s.Renderer);
        s.Renderer->TwoSidedLightingOff();
        s.Renderer->ResetCamera();
        s.View(20, 30);
        return true;
      } },
    { "gradient_opacity", LoadGradientOpacity },
    { "gradient_opacity_table2d", After(Table2D, LoadGradientOpacity) },
    { "gradient_opacity_table3d", After(Table3D, LoadGradientOpacity) },
    { "gradient_opacity_shaded_paper",
      [](Scene& s, int argc, char* argv[])
      {
        // Both, in the paper's layout and pipeline, in a volume of non-uniform scale: the
        // magnitude is measured in world units.
        if (!LoadGradientOpacity(s, argc, argv))
          return false;
        s.Mapper->SetPipelineToFragment();
        s.Mapper->SetMeshLayoutToPaper();
        vtkVolumeProperty* property = s.Volume->GetProperty();
        property->ShadeOn();
        property->SetSpecular(0.5);
        property->SetSpecularPower(20.0);
        s.Volume->SetScale(1.5, 0.7, 1.0);
        s.Renderer->ResetCamera();
        s.View(20, 30);
        return true;
      } },
  };
  scenes.insert(more.begin(), more.end());
}

// Every scene: which mesh, which view, which mapper settings, which bounds and checks.
const std::map<std::string, SceneSetup>& Scenes()
{
  static const std::map<std::string, SceneSetup> scenes = []
  {
    std::map<std::string, SceneSetup> all;
    AddMeshScenes(all);
    AddViewScenes(all);
    AddBlendAndClipScenes(all);
    AddIntegrationScenes(all);
    AddShadingScenes(all);
    return all;
  }();
  return scenes;
}
}

int TestTiledRayCastScenes(int argc, char* argv[])
{
  std::string name;
  for (int i = 1; i + 1 < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--scene"))
    {
      name = argv[i + 1];
    }
  }
  auto it = Scenes().find(name);
  if (it == Scenes().end())
  {
    std::cerr << "usage: --scene <name>; unknown scene '" << name << "'\n";
    return EXIT_FAILURE;
  }
  Scene scene;
  if (!it->second(scene, argc, argv))
  {
    return EXIT_FAILURE;
  }
  scene.Window->Render();
  if (!vtkOpenGLTiledRayCastVolumeMapper::IsSupported(scene.Window))
  {
    return VTK_SKIP_RETURN_CODE;
  }
  bool ok = Expect(scene.Mapper->GetStatistics()->GetRendered(), "the mapper rendered");
  ok = trctest::CheckAgainstReference(
         scene.Window, scene.Renderer, scene.Volume, scene.Bounds, name.c_str()) &&
    ok;
  if (scene.Check)
  {
    ok = scene.Check(scene) && ok;
  }
  const int regression = vtkRegressionTestImageThreshold(scene.Window, 5);
  return ok && regression == vtkTesting::PASSED ? EXIT_SUCCESS : EXIT_FAILURE;
}
