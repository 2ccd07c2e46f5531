/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetReferenceRenderer.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetReferenceRenderer.h"

#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkLightCollection.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTetRayIntegrator.h"
#include "vtkTetReferenceBlending.h"
#include "vtkTetReferenceCompositing.h"
#include "vtkTetReferenceMesh.h"
#include "vtkTetReferencePixelRays.h"
#include "vtkTetReferenceRayCaster.h"
#include "vtkTetReferenceScene.h"
#include "vtkTetReferenceShading.h"
#include "vtkTetReferenceVolume.h"
#include "vtkTimerLog.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

// The renderer is a pipeline of private classes: vtkTetReferenceMesh (preparation: the
// tetrahedra in world coordinates and their bounding volume hierarchy, vtkTetReferenceBVH),
// vtkTetReferencePixelRays (the camera's rays), vtkTetReferenceRayCaster (the tetrahedra each ray
// crosses, exactly) and vtkTetReferenceCompositing (front-to-back compositing with
// vtkTetRayIntegrator); for scenes of several volumes or with translucent layers,
// vtkTetReferenceIntermixing (all media and fragments of a ray in depth order) instead of the
// last (RenderScene()).
namespace
{
using Hit = vtkTetReferenceRayCaster::Hit;
using PixelRays = vtkTetReferencePixelRays;

// The arrays of a rendered image: "RGBA" (4 components, double or float) and "NumberOfTets"
// (the tetrahedra each ray crossed).
struct OutputArrays
{
  OutputArrays(bool doublePrecision, vtkIdType numberOfPixels)
  {
    if (doublePrecision)
    {
      this->RGBA = vtkSmartPointer<vtkDoubleArray>::New();
    }
    else
    {
      this->RGBA = vtkSmartPointer<vtkFloatArray>::New();
    }
    this->RGBA->SetName("RGBA");
    this->RGBA->SetNumberOfComponents(4);
    this->RGBA->SetNumberOfTuples(numberOfPixels);
    this->Counts->SetName("NumberOfTets");
    this->Counts->SetNumberOfTuples(numberOfPixels);
  }
  // The RGBA values as floats or as doubles (null for the other type).
  float* Float() const
  {
    auto* a = vtkFloatArray::SafeDownCast(this->RGBA);
    return a ? a->GetPointer(0) : nullptr;
  }
  double* Double() const
  {
    auto* a = vtkDoubleArray::SafeDownCast(this->RGBA);
    return a ? a->GetPointer(0) : nullptr;
  }
  vtkSmartPointer<vtkDataArray> RGBA;
  vtkNew<vtkIntArray> Counts;
};
} // namespace

//------------------------------------------------------------------------------
class vtkTetReferenceRenderer::vtkInternals
{
public:
  vtkTetReferenceMesh Mesh;
  // Shading of the composite blend mode (off unless the property shades).
  vtkTetReferenceShading Shading;

  // The property the integrator was initialised with.
  vtkVolumeProperty* Property = nullptr;
  vtkMTimeType PropertyMTime = 0;

  vtkSMPThreadLocal<std::vector<Hit>> Hits;

  // The scene: added volumes (prepared in Scene) and translucent layers.
  std::vector<vtkSmartPointer<vtkTetReferenceVolume>> Added;
  vtkTetReferenceScene Scene;
  struct LayerInput
  {
    vtkSmartPointer<vtkDataArray> RGBA;
    vtkSmartPointer<vtkFloatArray> Depth;
  };
  std::vector<LayerInput> Layers;

  // Every pixel's ray cast and composited into `rgba` (float or double, the other null) and
  // `counts` (the tetrahedra each ray crossed).
  void CastRays(const PixelRays& rays, vtkTetRayIntegrator* integrator,
    const vtkTetReferenceBlending::Settings& blending, float* rgbaFloat, double* rgbaDouble,
    int* counts);
};

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::vtkInternals::CastRays(const PixelRays& rays,
  vtkTetRayIntegrator* integrator, const vtkTetReferenceBlending::Settings& blending,
  float* rgbaFloat, double* rgbaDouble, int* counts)
{
  const int width = rays.Width;
  vtkSMPTools::For(0, rays.Height, 1,
    [&](vtkIdType rowBegin, vtkIdType rowEnd)
    {
      std::vector<Hit>& hits = this->Hits.Local();
      for (vtkIdType j = rowBegin; j < rowEnd; ++j)
      {
        for (int i = 0; i < width; ++i)
        {
          const vtkIdType pixel = j * width + i;
          // Zero unless a ray meets something.
          double result[4] = { 0.0, 0.0, 0.0, 0.0 };
          counts[pixel] = 0;
          double origin[3], d[3], zmin, zmax;
          if (rays.Get(i, static_cast<int>(j), origin, d, zmin, zmax))
          {
            vtkTetReferenceRayCaster::CastRay(this->Mesh, origin, d, zmin, zmax, hits);
            counts[pixel] = static_cast<int>(hits.size());
            const double unitLength = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            if (blending.Mode == 0)
            {
              vtkTetReferenceCompositing::CompositeRay(
                hits, this->Mesh.Transparent, integrator, unitLength, result, &this->Shading, d);
            }
            else
            {
              vtkTetReferenceBlending::BlendRay(
                hits, this->Mesh.Transparent, blending, unitLength, result);
            }
          }
          for (int k = 0; k < 4; ++k)
          {
            if (rgbaFloat)
            {
              rgbaFloat[4 * pixel + k] = static_cast<float>(result[k]);
            }
            else
            {
              rgbaDouble[4 * pixel + k] = result[k];
            }
          }
        }
      }
    });
}

//------------------------------------------------------------------------------
vtkStandardNewMacro(vtkTetReferenceRenderer);

//------------------------------------------------------------------------------
vtkTetReferenceRenderer::vtkTetReferenceRenderer()
  : Own(vtkTetReferenceVolume::New())
  , Camera(nullptr)
  , OpaqueDepth(nullptr)
  , DoublePrecisionOutput(0)
  , Output(vtkImageData::New())
  , Integrator(vtkTetRayIntegrator::New())
  , NumberOfTetrahedra(0)
  , NumberOfDegenerateTetrahedra(0)
  , LastPreparationTime(0.0)
  , LastRayCastTime(0.0)
  , Internals(new vtkInternals)
{
  this->ImageSize[0] = this->ImageSize[1] = 256;
  this->SampleOffset[0] = this->SampleOffset[1] = 0.5;
}

//------------------------------------------------------------------------------
vtkTetReferenceRenderer::~vtkTetReferenceRenderer()
{
  this->SetCamera(nullptr);
  this->SetOpaqueDepth(nullptr);
  this->SetClippingPlanes(nullptr);
  this->SetLights(nullptr);
  this->Own->Delete();
  this->Output->Delete();
  this->Integrator->Delete();
  delete this->Internals;
}

//------------------------------------------------------------------------------
vtkCxxSetObjectMacro(vtkTetReferenceRenderer, Camera, vtkCamera);
vtkCxxSetObjectMacro(vtkTetReferenceRenderer, Lights, vtkLightCollection);
vtkCxxSetObjectMacro(vtkTetReferenceRenderer, ClippingPlanes, vtkPlaneCollection);
vtkCxxSetObjectMacro(vtkTetReferenceRenderer, OpaqueDepth, vtkFloatArray);

//------------------------------------------------------------------------------
vtkMTimeType vtkTetReferenceRenderer::GetMTime()
{
  return std::max(this->Superclass::GetMTime(), this->Own->GetMTime());
}

//------------------------------------------------------------------------------
vtkImageData* vtkTetReferenceRenderer::GetOutput()
{
  return this->Output;
}

//------------------------------------------------------------------------------
vtkTetRayIntegrator* vtkTetReferenceRenderer::GetIntegrator()
{
  return this->Integrator;
}

//------------------------------------------------------------------------------
int vtkTetReferenceRenderer::Render()
{
  this->Output->Initialize();
  this->LastPreparationTime = 0.0;
  this->LastRayCastTime = 0.0;
  vtkInternals& in = *this->Internals;

  vtkVolumeProperty* property = this->Own->GetPropertyInForce();
  if (!in.Added.empty() || !in.Layers.empty())
  {
    return this->RenderScene(property);
  }
  const float* depth = nullptr;
  if (!this->CheckInputs(property, depth))
  {
    return 0;
  }
  if (!this->PrepareMesh(property) || !this->InitializeIntegrator(property))
  {
    return 0;
  }
  // Shading and gradient opacity apply to compositing only, as in VTK's volume mappers.
  in.Shading.Initialize(this->BlendMode == 0 ? property : nullptr, this->Lights, this->Camera,
    this->TwoSidedLighting != 0, &in.Mesh);

  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  const int width = this->ImageSize[0], height = this->ImageSize[1];
  const vtkIdType numPixels = static_cast<vtkIdType>(width) * height;
  PixelRays rays;
  rays.SetUp(
    this->Camera, width, height, this->SampleOffset, depth, in.Mesh.Center, this->ClippingPlanes);
  OutputArrays output(this->DoublePrecisionOutput != 0, numPixels);
  // The blend mode's settings: the data's scalar range normalises the scalar, as the mapper's.
  vtkTetReferenceBlending::Settings blending;
  blending.Mode = this->BlendMode;
  blending.Property = property;
  blending.AverageRange[0] = this->AverageIPScalarRange[0];
  blending.AverageRange[1] = this->AverageIPScalarRange[1];
  blending.ScalarRange[0] = VTK_DOUBLE_MAX;
  blending.ScalarRange[1] = VTK_DOUBLE_MIN;
  if (blending.Mode != 0) // compositing needs no range: no pass over the scalars per image
  {
    for (double v : in.Mesh.Scalars)
    {
      if (std::isfinite(v))
      {
        blending.ScalarRange[0] = std::min(blending.ScalarRange[0], v);
        blending.ScalarRange[1] = std::max(blending.ScalarRange[1], v);
      }
    }
  }
  in.CastRays(rays, this->Integrator, blending, output.Float(), output.Double(),
    output.Counts->GetPointer(0));

  this->StoreOutput(output.RGBA, output.Counts);
  timer->StopTimer();
  this->LastRayCastTime = timer->GetElapsedTime();
  return 1;
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::StoreOutput(vtkDataArray* rgba, vtkDataArray* counts)
{
  this->Output->SetDimensions(this->ImageSize[0], this->ImageSize[1], 1);
  this->Output->GetPointData()->SetScalars(rgba);
  this->Output->GetPointData()->AddArray(counts);
}

//------------------------------------------------------------------------------
// Everything Render() needs is there and fits (an error for the first thing that does not);
// `depth` gets the opaque depth's values, if any.
bool vtkTetReferenceRenderer::CheckInputs(vtkVolumeProperty* property, const float*& depth)
{
  vtkDataSet* input = this->GetInput();
  if (!input)
  {
    vtkErrorMacro("No input.");
    return false;
  }
  if (input->GetNumberOfPoints() == 0 || input->GetNumberOfCells() == 0)
  {
    vtkErrorMacro("The input is empty.");
    return false;
  }
  if (!property)
  {
    vtkErrorMacro("No volume property.");
    return false;
  }
  return this->CheckView(depth);
}

//------------------------------------------------------------------------------
// The camera, the image size and the opaque depth (an error for the first that does not fit);
// `depth` gets the opaque depth's values, if any.
bool vtkTetReferenceRenderer::CheckView(const float*& depth)
{
  if (!this->Camera)
  {
    vtkErrorMacro("No camera.");
    return false;
  }
  const int width = this->ImageSize[0], height = this->ImageSize[1];
  if (width <= 0 || height <= 0 || static_cast<double>(width) * height > 1e9)
  {
    vtkErrorMacro("Bad image size " << width << " x " << height << ".");
    return false;
  }
  const vtkIdType numPixels = static_cast<vtkIdType>(width) * height;
  depth = nullptr;
  if (this->OpaqueDepth)
  {
    if (this->OpaqueDepth->GetNumberOfTuples() * this->OpaqueDepth->GetNumberOfComponents() !=
      numPixels)
    {
      vtkErrorMacro("The opaque depth has " << this->OpaqueDepth->GetNumberOfValues()
                                            << " values; the image has " << numPixels
                                            << " pixels.");
      return false;
    }
    depth = this->OpaqueDepth->GetPointer(0);
  }
  return true;
}

//------------------------------------------------------------------------------
// The mesh, prepared again only when what it depends on changed.
bool vtkTetReferenceRenderer::PrepareMesh(vtkVolumeProperty* property)
{
  vtkInternals& in = *this->Internals;
  vtkTetReferenceScene::Source source = vtkTetReferenceScene::MakeSource(this->Own);
  source.Property = property;
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  std::string error;
  bool rebuilt = false;
  vtkIdType degenerate = 0;
  if (!vtkTetReferenceScene::PrepareMesh(source, in.Mesh, rebuilt, degenerate, error))
  {
    vtkErrorMacro(<< error);
    return false;
  }
  if (!rebuilt)
  {
    return true;
  }
  timer->StopTimer();
  this->LastPreparationTime = timer->GetElapsedTime();
  this->NumberOfTetrahedra = static_cast<vtkIdType>(in.Mesh.Transparent.size());
  this->NumberOfDegenerateTetrahedra = degenerate;
  this->NumberOfOverlappingTetrahedra = static_cast<vtkIdType>(in.Mesh.NumberOfOverlapping);
  return true;
}

//------------------------------------------------------------------------------
// The integrator, initialised again only when the property changed.
bool vtkTetReferenceRenderer::InitializeIntegrator(vtkVolumeProperty* property)
{
  vtkInternals& in = *this->Internals;
  if (!vtkTetReferenceScene::InitializeIntegrator(
        this->Integrator, property, in.Property, in.PropertyMTime))
  {
    vtkErrorMacro("The volume property cannot be integrated.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
// Render() of a scene (several volumes, translucent layers): the renderer's own input as volume
// 0 when it has one, then the added volumes, and the layers, all through
// vtkTetReferenceIntermixing.
int vtkTetReferenceRenderer::RenderScene(vtkVolumeProperty* property)
{
  vtkInternals& in = *this->Internals;
  const bool ownInput = this->GetInput() != nullptr;
  const float* depth = nullptr;
  if (ownInput && !this->CheckInputs(property, depth))
  {
    return 0;
  }
  if (!ownInput && !this->CheckView(depth))
  {
    return 0;
  }
  if (this->BlendMode != 0)
  {
    vtkErrorMacro("Blend mode " << this->BlendMode
                                << " renders one volume without translucent layers; a scene of "
                                   "several volumes or with layers needs the composite mode.");
    return 0;
  }
  for (size_t v = 0; v <= in.Added.size(); ++v)
  {
    vtkVolumeProperty* p =
      v == 0 ? (ownInput ? property : nullptr) : in.Added[v - 1]->GetPropertyInForce();
    if (vtkTetReferenceShading::DependsOnGradient(p))
    {
      // The mixture of overlapping media would need each medium's shaded emission apart.
      vtkErrorMacro("Volume " << (ownInput ? v : v - 1)
                              << " is shaded or has a gradient opacity: these render one volume "
                                 "without translucent layers, not a scene.");
      return 0;
    }
  }
  const vtkIdType numPixels = static_cast<vtkIdType>(this->ImageSize[0]) * this->ImageSize[1];
  vtkTetReferenceIntermixing scene;
  for (size_t l = 0; l < in.Layers.size(); ++l)
  {
    std::string error;
    if (!vtkTetReferenceScene::CheckLayer(in.Layers[l].RGBA, in.Layers[l].Depth, numPixels, error))
    {
      vtkErrorMacro("Translucent layer " << l << ": " << error);
      return 0;
    }
    vtkTetReferenceIntermixing::Layer layer;
    layer.RGBA.resize(4 * static_cast<size_t>(numPixels));
    for (vtkIdType p = 0; p < numPixels; ++p)
    {
      in.Layers[l].RGBA->GetTuple(p, &layer.RGBA[4 * p]);
    }
    layer.Depth = in.Layers[l].Depth->GetPointer(0);
    scene.Layers.push_back(std::move(layer));
  }
  // The volumes: figures summed over them.
  vtkIdType tetrahedra[3] = { 0, 0, 0 };
  if (ownInput)
  {
    if (!this->PrepareMesh(property) || !this->InitializeIntegrator(property))
    {
      return 0;
    }
    scene.Media.push_back({ &in.Mesh, this->Integrator });
    tetrahedra[0] = this->NumberOfTetrahedra;
    tetrahedra[1] = this->NumberOfDegenerateTetrahedra;
    tetrahedra[2] = this->NumberOfOverlappingTetrahedra;
  }
  std::vector<vtkTetReferenceScene::Source> sources;
  for (vtkTetReferenceVolume* volume : in.Added)
  {
    sources.push_back(vtkTetReferenceScene::MakeSource(volume));
  }
  std::string error;
  if (!in.Scene.Prepare(sources, ownInput ? 1 : 0, tetrahedra, this->LastPreparationTime, error))
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  in.Scene.AppendMedia(scene.Media);
  scene.SetReference();
  this->NumberOfTetrahedra = tetrahedra[0];
  this->NumberOfDegenerateTetrahedra = tetrahedra[1];
  this->NumberOfOverlappingTetrahedra = tetrahedra[2];

  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  PixelRays rays; // in world coordinates: no centre
  rays.SetUp(this->Camera, this->ImageSize[0], this->ImageSize[1], this->SampleOffset, depth,
    nullptr, this->ClippingPlanes);
  OutputArrays output(this->DoublePrecisionOutput != 0, numPixels);
  vtkTetReferenceScene::CastRays(
    scene, rays, output.Float(), output.Double(), output.Counts->GetPointer(0));
  this->StoreOutput(output.RGBA, output.Counts);
  timer->StopTimer();
  this->LastRayCastTime = timer->GetElapsedTime();
  return 1;
}

//------------------------------------------------------------------------------
vtkTetReferenceVolume* vtkTetReferenceRenderer::AddVolume(
  vtkDataSet* input, vtkVolumeProperty* property, vtkMatrix4x4* matrix)
{
  vtkNew<vtkTetReferenceVolume> volume;
  volume->SetInputData(input);
  volume->SetVolumeProperty(property);
  volume->SetMatrix(matrix);
  this->AddVolume(volume);
  return volume;
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::AddVolume(vtkTetReferenceVolume* volume)
{
  if (!volume)
  {
    vtkErrorMacro("AddVolume: no volume given; nothing added.");
    return;
  }
  this->Internals->Added.emplace_back(volume);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::RemoveAllVolumes()
{
  this->Internals->Added.clear();
  this->Internals->Scene.Clear();
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkTetReferenceRenderer::GetNumberOfAddedVolumes()
{
  return static_cast<int>(this->Internals->Added.size());
}

//------------------------------------------------------------------------------
vtkTetReferenceVolume* vtkTetReferenceRenderer::GetAddedVolume(int i)
{
  if (i < 0 || i >= this->GetNumberOfAddedVolumes())
  {
    vtkErrorMacro(
      "No added volume " << i << " (there are " << this->GetNumberOfAddedVolumes() << ").");
    return nullptr;
  }
  return this->Internals->Added[i];
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::AddTranslucentLayer(vtkDataArray* rgba, vtkFloatArray* depth)
{
  if (!rgba || !depth)
  {
    vtkErrorMacro("AddTranslucentLayer needs an RGBA array and a depth array; nothing added.");
    return;
  }
  this->Internals->Layers.push_back({ rgba, depth });
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::RemoveAllTranslucentLayers()
{
  this->Internals->Layers.clear();
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkTetReferenceRenderer::GetNumberOfTranslucentLayers()
{
  return static_cast<int>(this->Internals->Layers.size());
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Own volume (input, property, matrix, scalars):\n";
  this->Own->PrintSelf(os, indent.GetNextIndent());
  os << indent << "Camera: " << this->Camera << "\n";
  os << indent << "ImageSize: " << this->ImageSize[0] << " x " << this->ImageSize[1] << "\n";
  os << indent << "OpaqueDepth: " << this->OpaqueDepth << "\n";
  os << indent << "ClippingPlanes: " << this->ClippingPlanes << "\n";
  os << indent << "Lights: " << this->Lights << "\n";
  os << indent << "TwoSidedLighting: " << this->TwoSidedLighting << "\n";
  os << indent << "BlendMode: " << this->BlendMode << "\n";
  os << indent << "AverageIPScalarRange: " << this->AverageIPScalarRange[0] << " "
     << this->AverageIPScalarRange[1] << "\n";
  os << indent << "SampleOffset: " << this->SampleOffset[0] << ", " << this->SampleOffset[1]
     << "\n";
  os << indent << "DoublePrecisionOutput: " << this->DoublePrecisionOutput << "\n";
  os << indent << "NumberOfAddedVolumes: " << this->Internals->Added.size() << "\n";
  for (const vtkSmartPointer<vtkTetReferenceVolume>& volume : this->Internals->Added)
  {
    volume->PrintSelf(os, indent.GetNextIndent());
  }
  os << indent << "NumberOfTranslucentLayers: " << this->Internals->Layers.size() << "\n";
  os << indent << "NumberOfTetrahedra: " << this->NumberOfTetrahedra << "\n";
  os << indent << "NumberOfDegenerateTetrahedra: " << this->NumberOfDegenerateTetrahedra << "\n";
  os << indent << "LastPreparationTime: " << this->LastPreparationTime << "\n";
  os << indent << "LastRayCastTime: " << this->LastRayCastTime << "\n";
  os << indent << "Integrator:\n";
  this->Integrator->PrintSelf(os, indent.GetNextIndent());
}
