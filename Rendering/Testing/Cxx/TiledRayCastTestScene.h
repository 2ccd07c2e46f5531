/*=========================================================================

  Program:   TiledRayCast
  Module:    TiledRayCastTestScene.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Helpers shared by the mapper's image tests: reading the test meshes, a transfer function (the
// ramp of TiledRayCastSharedScenes.h, which the benchmarks use too), a mapper alone in a window
// (WatchedVolume), an opaque ball, cell scalars, the views of the small blocks, and the check of
// a rendered image against the exact reference renderer (every baseline image of the project is
// also checked this way, with the bounds stated by each test).
#ifndef TiledRayCastTestScene_h
#define TiledRayCastTestScene_h

#include "TiledRayCastMessageCounter.h" // For trctest::MessageCounter
#include "TiledRayCastSharedScenes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPointDataToCellData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkTestUtilities.h"
#include "vtkTetReferenceRenderer.h"
#include "vtkTetScalarSelection.h"
#include "vtkTiledRayCastStatistics.h"
#include "vtkTiledRayCastVolumeMapper.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace trctest
{
// Prints what failed; returns the condition (checks are chained with `ok = Expect(...) && ok`).
inline bool Expect(bool condition, const std::string& what)
{
  if (!condition)
  {
    std::cerr << "check failed: " << what << "\n";
  }
  return condition;
}

// A mapper of `grid` with `property`, its warnings counted, alone in a window of `size` pixels
// (not yet rendered, camera reset).
struct WatchedVolume
{
  vtkNew<vtkTiledRayCastVolumeMapper> Mapper;
  vtkNew<MessageCounter> Warnings;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<MessageCounter> Errors; // counts the mapper's errors once CountErrors() is called

  WatchedVolume(vtkUnstructuredGrid* grid, vtkVolumeProperty* property, int size)
    : WatchedVolume(property, size)
  {
    this->Mapper->SetInputData(grid);
    this->Renderer->ResetCamera();
  }

  // The same without an input: the caller connects the mapper (a composite input, a pipeline)
  // and places the camera.
  WatchedVolume(vtkVolumeProperty* property, int size)
  {
    this->Mapper->AddObserver(vtkCommand::WarningEvent, this->Warnings);
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(property);
    this->Renderer->AddVolume(this->Volume);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(size, size);
    this->Window->AddRenderer(this->Renderer);
  }

  // The mapper's errors are counted in Errors from now on, instead of failing the test.
  MessageCounter* CountErrors()
  {
    this->Mapper->AddObserver(vtkCommand::ErrorEvent, this->Errors);
    return this->Errors;
  }
};

// An opaque sphere (VTK's default material) of `radius` around `centre`, with `resolution`
// steps in theta and phi (VTK's default, 8, where not given): geometry inside a volume.
inline vtkSmartPointer<vtkActor> MakeBall(const double centre[3], double radius, int resolution = 8)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(centre[0], centre[1], centre[2]);
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(resolution);
  sphere->SetPhiResolution(resolution);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  auto ball = vtkSmartPointer<vtkActor>::New();
  ball->SetMapper(mapper);
  return ball;
}

// The box of one voxel of `spacing` at `origin`, split into tetrahedra (vtkDataSetTriangleFilter),
// with point scalars "scalar" = value(point) as float.
inline vtkSmartPointer<vtkUnstructuredGrid> TetrahedralBox(const std::array<double, 3>& spacing,
  const std::array<double, 3>& origin, const std::function<double(const double*)>& value)
{
  vtkNew<vtkImageData> box;
  box->SetDimensions(2, 2, 2);
  box->SetSpacing(spacing.data());
  box->SetOrigin(origin.data());
  vtkNew<vtkFloatArray> scalars;
  scalars->SetName("scalar");
  for (vtkIdType i = 0; i < 8; ++i)
  {
    scalars->InsertNextValue(static_cast<float>(value(box->GetPoint(i))));
  }
  box->GetPointData()->SetScalars(scalars);
  vtkNew<vtkDataSetTriangleFilter> tets;
  tets->SetInputData(box);
  tets->Update();
  return tets->GetOutput();
}

// `grid` with its point data averaged to cell data (vtkPointDataToCellData); without
// `keepPointData` the points lose their arrays: cell scalars only.
inline vtkSmartPointer<vtkUnstructuredGrid> WithCellScalars(
  vtkDataSet* grid, bool keepPointData = true)
{
  vtkNew<vtkPointDataToCellData> toCells;
  toCells->SetInputData(grid);
  toCells->Update();
  vtkSmartPointer<vtkUnstructuredGrid> cells =
    vtkUnstructuredGrid::SafeDownCast(toCells->GetOutput());
  if (!keepPointData)
  {
    cells->GetPointData()->Initialize();
  }
  return cells;
}

// Points `camera` at the origin from -y, z up, then turns it by `azimuth` and `elevation`
// degrees: the views of the small synthetic blocks (reset the camera to fit them afterwards).
inline void LookFrom(vtkCamera* camera, double azimuth, double elevation)
{
  camera->SetPosition(0, -1, 0);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 0, 1);
  camera->Azimuth(azimuth);
  camera->Elevation(elevation);
  camera->OrthogonalizeViewUp();
}

// Whether this machine's OpenGL can run the mapper (tests skip, VTK_SKIP_RETURN_CODE, where not).
inline bool RenderingSupported()
{
  vtkNew<vtkRenderWindow> window;
  window->SetSize(8, 8);
  window->Render();
  vtkNew<vtkTiledRayCastVolumeMapper> mapper;
  vtkNew<vtkVolumeProperty> property;
  return mapper->IsRenderSupported(window, property) != 0;
}

// A mesh of Testing/Data/Meshes, found through the test driver's -D argument.
inline vtkSmartPointer<vtkUnstructuredGrid> ReadMesh(int argc, char* argv[], const char* file)
{
  const std::string name = std::string("Meshes/") + file;
  char* path = vtkTestUtilities::ExpandDataFileName(argc, argv, name.c_str());
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path);
  reader->Update();
  delete[] path;
  vtkSmartPointer<vtkUnstructuredGrid> grid = reader->GetOutput();
  if (!grid || grid->GetNumberOfCells() == 0)
  {
    std::cerr << "cannot read " << name << "\n";
    return nullptr;
  }
  return grid;
}

// The ramp of the mapper's scenes, shared with the benchmarks (TiledRayCastSharedScenes.h).
using trcscene::MakeProperty;
using trcscene::MakePropertyFor;

// Bounds on the difference between the window's image and the exact reference, in 1/255.
// The defaults hold for partial pre-integration, exact up to float arithmetic and the 8-bit
// framebuffer: what remains is rounding, of the colour and of the blend over the background in
// 8 bits (a difference of 1 on many pixels: RMSE up to 0.51 on llvmpipe). Measured on llvmpipe
// since the Psi table is read the right way round: at most 1 on every pixel of every image of
// the suite (up to 8 before); the bounds leave room for a GPU's own float rounding.
struct Bounds
{
  double RMSE = 0.75;
  double P999 = 1.0; // 99.9th percentile of per-channel differences
  double Max = 2.0;
};

// Renders `reference` (set up for the scene, its opaque depth the window's), composites it over
// `behind` (the window's pixels without the volumes) and compares that with `pixels` (the
// window's pixels with them), both width x height RGB, within `bounds`; prints the differences
// and `mapper`'s statistics. The end of CheckAgainstReference, shared with the tests of scenes
// of several volumes (TestTiledRayCastOverlapping).
inline bool CompareWithReference(vtkTetReferenceRenderer* reference, vtkUnsignedCharArray* behind,
  vtkUnsignedCharArray* pixels, int width, int height, const Bounds& bounds,
  const std::string& label, vtkTiledRayCastVolumeMapper* mapper)
{
  if (!reference->Render())
  {
    std::cerr << label << ": the reference renderer failed\n";
    return false;
  }
  // The premultiplied reference over what lies behind, rounded as a framebuffer does.
  vtkDataArray* rgba = reference->GetOutput()->GetPointData()->GetArray("RGBA");
  vtkNew<vtkUnsignedCharArray> composited;
  composited->SetName("RGB");
  composited->SetNumberOfComponents(3);
  composited->SetNumberOfTuples(static_cast<vtkIdType>(width) * height);
  for (vtkIdType i = 0; i < composited->GetNumberOfTuples(); ++i)
  {
    const double alpha = rgba->GetComponent(i, 3);
    for (int c = 0; c < 3; ++c)
    {
      const double value =
        rgba->GetComponent(i, c) + (1.0 - alpha) * behind->GetValue(3 * i + c) / 255.0;
      composited->SetValue(3 * i + c,
        static_cast<unsigned char>(std::lround(255.0 * std::min(std::max(value, 0.0), 1.0))));
    }
  }
  vtkNew<vtkImageData> expected;
  expected->SetDimensions(width, height, 1);
  expected->GetPointData()->SetScalars(composited);
  vtkNew<vtkImageData> actual;
  actual->SetDimensions(width, height, 1);
  pixels->SetName("RGB");
  actual->GetPointData()->SetScalars(pixels);
  double stats[3] = { 0, 0, 0 };
  if (!vtkTetReferenceRenderer::CompareImages(actual, expected, stats))
  {
    std::cerr << label << ": images cannot be compared\n";
    return false;
  }
  std::cout << label << " vs exact reference (1/255): RMSE " << stats[0] << ", 99.9th percentile "
            << stats[1] << ", max " << stats[2] << " (bounds " << bounds.RMSE << ", " << bounds.P999
            << ", " << bounds.Max << ")\n";
  std::cout << label << ": " << mapper->GetStatistics()->GetSummary() << "\n";
  const bool ok = stats[0] <= bounds.RMSE && stats[1] <= bounds.P999 && stats[2] <= bounds.Max;
  if (!ok)
  {
    std::cerr << label << ": difference to the exact reference exceeds its bounds\n";
  }
  return ok;
}

// Renders the exact reference of what `volume` shows in `renderer` (same camera, viewport size,
// volume matrix, opaque depth from the window's depth buffer and background), reads the window's
// pixels and compares. Prints the figures; returns false when a bound is exceeded. The window
// must have been rendered. `configure`, when given, changes the reference's settings (its input,
// scalar selection) after they were copied from the mapper: for checks against an independent
// statement of what should be drawn.
inline bool CheckAgainstReference(vtkRenderWindow* window, vtkRenderer* renderer, vtkVolume* volume,
  const Bounds& bounds, const char* label = "image",
  const std::function<void(vtkTetReferenceRenderer*)>& configure = nullptr)
{
  auto* mapper = vtkTiledRayCastVolumeMapper::SafeDownCast(volume->GetMapper());
  if (!mapper)
  {
    std::cerr << label << ": the volume has no tiled ray-cast mapper\n";
    return false;
  }
  int width = 0, height = 0, x0 = 0, y0 = 0;
  renderer->GetTiledSizeAndOrigin(&width, &height, &x0, &y0);

  // What lies behind the volume: the scene rendered without it (background and opaque
  // geometry), over which the reference is composited.
  volume->VisibilityOff();
  window->Render();
  vtkNew<vtkUnsignedCharArray> behind;
  window->GetPixelData(x0, y0, x0 + width - 1, y0 + height - 1, 0, behind, 0);
  volume->VisibilityOn();
  window->Render();

  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetPixelData(x0, y0, x0 + width - 1, y0 + height - 1, 0, pixels, 0);
  vtkNew<vtkFloatArray> depth;
  window->GetZbufferData(x0, y0, x0 + width - 1, y0 + height - 1, depth);

  vtkNew<vtkTetReferenceRenderer> reference;
  reference->SetInputData(mapper->GetInput());
  reference->GetScalarSelection()->CopySettings(mapper->GetScalarSelection());
  reference->SetVolumeProperty(volume->GetProperty());
  reference->SetCamera(renderer->GetActiveCamera());
  reference->SetImageSize(width, height);
  reference->SetVolume(volume);
  reference->SetOpaqueDepth(depth);
  reference->SetClippingPlanes(mapper->GetClippingPlanes());
  reference->SetBlendMode(mapper->GetBlendMode());
  reference->SetAverageIPScalarRange(mapper->GetAverageIPScalarRange());
  // Shading: the renderer's lights, placed for this camera by the last Render().
  reference->SetLights(renderer->GetLights());
  reference->SetTwoSidedLighting(renderer->GetTwoSidedLighting());
  if (configure)
  {
    configure(reference);
  }
  return CompareWithReference(reference, behind, pixels, width, height, bounds, label, mapper);
}
}

#endif
// VTK-HeaderTest-Exclude: TiledRayCastTestScene.h
