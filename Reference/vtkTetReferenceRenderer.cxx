/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetReferenceRenderer.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetReferenceRenderer.h"

#include "vtkAbstractMapper.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkScalarsToColors.h"
#include "vtkSmartPointer.h"
#include "vtkTetRayIntegrator.h"
#include "vtkTetReferenceBlending.h"
#include "vtkTetReferenceCompositing.h"
#include "vtkTetReferenceMesh.h"
#include "vtkTetReferenceRayCaster.h"
#include "vtkTetScalarSelection.h"
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
// vtkTetReferenceRayCaster (the tetrahedra each ray crosses, exactly) and
// vtkTetReferenceCompositing (front-to-back compositing with vtkTetRayIntegrator).
namespace
{
using Hit = vtkTetReferenceRayCaster::Hit;

//------------------------------------------------------------------------------
// The camera's rays through the pixels of the image, in the prepared mesh's frame (world
// coordinates minus its centre), each clipped to the opaque depth and the clipping planes.
class PixelRays
{
public:
  int Width = 0, Height = 0;
  double OffsetX = 0.5, OffsetY = 0.5;
  const float* Depth = nullptr;
  double Inverse[16]; // clip coordinates to world coordinates
  const double* Center = nullptr;
  // Clipping planes in the rays' frame, (n, d) with n.x + d >= 0 kept.
  std::vector<std::array<double, 4>> Clipping;

  // The planes (world coordinates, the side the normal points to kept) in the rays' frame;
  // call after Center is set.
  void SetClippingPlanes(vtkPlaneCollection* planes)
  {
    this->Clipping.clear();
    for (int k = 0; planes && k < planes->GetNumberOfItems(); ++k)
    {
      vtkPlane* plane = planes->GetItem(k);
      std::array<double, 4> h;
      plane->GetNormal(h.data());
      double origin[3];
      plane->GetOrigin(origin);
      h[3] = 0.0;
      for (int r = 0; r < 3; ++r)
      {
        h[3] -= h[r] * (origin[r] - this->Center[r]);
      }
      if (h[0] != 0.0 || h[1] != 0.0 || h[2] != 0.0)
      {
        this->Clipping.push_back(h);
      }
    }
  }

  void Unproject(double x, double y, double z, double p[3]) const
  {
    const double* inverse = this->Inverse;
    double h[4];
    for (int r = 0; r < 4; ++r)
    {
      h[r] =
        inverse[4 * r] * x + inverse[4 * r + 1] * y + inverse[4 * r + 2] * z + inverse[4 * r + 3];
    }
    for (int r = 0; r < 3; ++r)
    {
      p[r] = h[r] / h[3] - this->Center[r];
    }
  }

  // The ray of pixel (i, j): origin + z d for z in (zmin, zmax). False for a pixel with no ray
  // (a degenerate direction, opaque geometry at the near plane, or clipped away).
  bool Get(int i, int j, double origin[3], double d[3], double& zmin, double& zmax) const
  {
    const vtkIdType pixel = static_cast<vtkIdType>(j) * this->Width + i;
    const double x = 2.0 * (i + this->OffsetX) / this->Width - 1.0;
    const double y = 2.0 * (j + this->OffsetY) / this->Height - 1.0;
    double nearP[3], farP[3];
    this->Unproject(x, y, -1.0, nearP);
    this->Unproject(x, y, 1.0, farP);
    for (int k = 0; k < 3; ++k)
    {
      d[k] = farP[k] - nearP[k];
    }
    const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    if (!(dd > 0.0) || !std::isfinite(dd))
    {
      return false;
    }
    double lambdaMax = 1.0;
    if (this->Depth && this->Depth[pixel] < 1.0f)
    {
      double p[3];
      this->Unproject(x, y, 2.0 * this->Depth[pixel] - 1.0, p);
      lambdaMax =
        ((p[0] - nearP[0]) * d[0] + (p[1] - nearP[1]) * d[1] + (p[2] - nearP[2]) * d[2]) / dd;
      lambdaMax = std::min(1.0, std::max(0.0, lambdaMax));
    }
    // The kept half-spaces of the clipping planes cut the ray to [lambdaMin, lambdaMax].
    double lambdaMin = 0.0;
    for (const std::array<double, 4>& h : this->Clipping)
    {
      const double at0 = h[0] * nearP[0] + h[1] * nearP[1] + h[2] * nearP[2] + h[3];
      const double rate = h[0] * d[0] + h[1] * d[1] + h[2] * d[2];
      if (rate > 0.0)
      {
        lambdaMin = std::max(lambdaMin, -at0 / rate);
      }
      else if (rate < 0.0)
      {
        lambdaMax = std::min(lambdaMax, -at0 / rate);
      }
      else if (at0 < 0.0)
      {
        lambdaMax = -1.0;
      }
    }
    if (!(lambdaMax > 0.0) || !(lambdaMax > lambdaMin))
    {
      return false;
    }
    // Measure the ray from its point nearest to the mesh centre (the origin here): the vertex
    // coordinates of the ray frame then stay as small as the mesh.
    const double lambdaC = std::min(
      lambdaMax, std::max(0.0, -(nearP[0] * d[0] + nearP[1] * d[1] + nearP[2] * d[2]) / dd));
    for (int k = 0; k < 3; ++k)
    {
      origin[k] = nearP[k] + lambdaC * d[k];
    }
    zmin = lambdaMin - lambdaC;
    zmax = lambdaMax - lambdaC;
    return true;
  }
};
} // namespace

//------------------------------------------------------------------------------
class vtkTetReferenceRenderer::vtkInternals
{
public:
  vtkTetReferenceMesh Mesh;

  // The property the integrator was initialised with.
  vtkVolumeProperty* Property = nullptr;
  vtkMTimeType PropertyMTime = 0;

  vtkSMPThreadLocal<std::vector<Hit>> Hits;

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
                hits, this->Mesh.Transparent, integrator, unitLength, result);
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
  : Input(nullptr)
  , ScalarMode(VTK_SCALAR_MODE_DEFAULT)
  , ArrayAccessMode(VTK_GET_ARRAY_BY_ID)
  , ArrayId(-1)
  , ArrayName(nullptr)
  , VectorMode(vtkTetScalarSelection::DEFAULT)
  , VectorComponent(0)
  , VolumeProperty(nullptr)
  , Camera(nullptr)
  , VolumeMatrix(vtkMatrix4x4::New())
  , Volume(nullptr)
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
  this->SetInputData(nullptr);
  this->SetVolumeProperty(nullptr);
  this->SetCamera(nullptr);
  this->SetVolume(nullptr);
  this->SetOpaqueDepth(nullptr);
  this->SetClippingPlanes(nullptr);
  this->SetArrayName(nullptr);
  this->VolumeMatrix->Delete();
  this->Output->Delete();
  this->Integrator->Delete();
  delete this->Internals;
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::SetInputData(vtkDataSet* input)
{
  vtkSetObjectBodyMacro(Input, vtkDataSet, input);
}

//------------------------------------------------------------------------------
vtkDataSet* vtkTetReferenceRenderer::GetInput()
{
  return this->Input;
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::SetVolumeProperty(vtkVolumeProperty* property)
{
  vtkSetObjectBodyMacro(VolumeProperty, vtkVolumeProperty, property);
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::SetCamera(vtkCamera* camera)
{
  vtkSetObjectBodyMacro(Camera, vtkCamera, camera);
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::SetVolume(vtkVolume* volume)
{
  vtkSetObjectBodyMacro(Volume, vtkVolume, volume);
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::SetClippingPlanes(vtkPlaneCollection* planes)
{
  vtkSetObjectBodyMacro(ClippingPlanes, vtkPlaneCollection, planes);
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::SetOpaqueDepth(vtkFloatArray* depth)
{
  vtkSetObjectBodyMacro(OpaqueDepth, vtkFloatArray, depth);
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::SetVolumeMatrix(vtkMatrix4x4* matrix)
{
  if (matrix)
  {
    this->VolumeMatrix->DeepCopy(matrix);
  }
  else
  {
    this->VolumeMatrix->Identity();
  }
  this->Modified();
}

//------------------------------------------------------------------------------
vtkMatrix4x4* vtkTetReferenceRenderer::GetVolumeMatrix()
{
  return this->VolumeMatrix;
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::SetScalarModeToDefault()
{
  this->SetScalarMode(VTK_SCALAR_MODE_DEFAULT);
}
void vtkTetReferenceRenderer::SetScalarModeToUsePointData()
{
  this->SetScalarMode(VTK_SCALAR_MODE_USE_POINT_DATA);
}
void vtkTetReferenceRenderer::SetScalarModeToUseCellData()
{
  this->SetScalarMode(VTK_SCALAR_MODE_USE_CELL_DATA);
}
void vtkTetReferenceRenderer::SetScalarModeToUsePointFieldData()
{
  this->SetScalarMode(VTK_SCALAR_MODE_USE_POINT_FIELD_DATA);
}
void vtkTetReferenceRenderer::SetScalarModeToUseCellFieldData()
{
  this->SetScalarMode(VTK_SCALAR_MODE_USE_CELL_FIELD_DATA);
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::SelectScalarArray(int arrayNum)
{
  if (this->ArrayId == arrayNum && this->ArrayAccessMode == VTK_GET_ARRAY_BY_ID)
  {
    return;
  }
  this->ArrayId = arrayNum;
  this->ArrayAccessMode = VTK_GET_ARRAY_BY_ID;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::SelectScalarArray(const char* arrayName)
{
  if (!arrayName)
  {
    return;
  }
  this->SetArrayName(arrayName);
  this->ArrayAccessMode = VTK_GET_ARRAY_BY_NAME;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::SetVectorModeToDefault()
{
  this->SetVectorMode(vtkTetScalarSelection::DEFAULT);
}
void vtkTetReferenceRenderer::SetVectorModeToComponent()
{
  this->SetVectorMode(vtkScalarsToColors::COMPONENT);
}
void vtkTetReferenceRenderer::SetVectorModeToMagnitude()
{
  this->SetVectorMode(vtkScalarsToColors::MAGNITUDE);
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

  vtkVolumeProperty* property = this->VolumeProperty;
  if (!property && this->Volume)
  {
    property = this->Volume->GetProperty();
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

  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  const int width = this->ImageSize[0], height = this->ImageSize[1];
  const vtkIdType numPixels = static_cast<vtkIdType>(width) * height;
  PixelRays rays;
  rays.Width = width;
  rays.Height = height;
  rays.OffsetX = this->SampleOffset[0];
  rays.OffsetY = this->SampleOffset[1];
  rays.Depth = depth;
  rays.Center = in.Mesh.Center;
  // Clip coordinates of the camera to world coordinates.
  vtkMatrix4x4::DeepCopy(rays.Inverse,
    this->Camera->GetCompositeProjectionTransformMatrix(
      static_cast<double>(width) / height, -1.0, 1.0));
  vtkMatrix4x4::Invert(rays.Inverse, rays.Inverse);
  rays.SetClippingPlanes(this->ClippingPlanes);

  vtkSmartPointer<vtkDataArray> rgba;
  if (this->DoublePrecisionOutput)
  {
    rgba = vtkSmartPointer<vtkDoubleArray>::New();
  }
  else
  {
    rgba = vtkSmartPointer<vtkFloatArray>::New();
  }
  rgba->SetName("RGBA");
  rgba->SetNumberOfComponents(4);
  rgba->SetNumberOfTuples(numPixels);
  vtkNew<vtkIntArray> counts;
  counts->SetName("NumberOfTets");
  counts->SetNumberOfTuples(numPixels);
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
  in.CastRays(rays, this->Integrator, blending,
    this->DoublePrecisionOutput ? nullptr : vtkFloatArray::SafeDownCast(rgba)->GetPointer(0),
    this->DoublePrecisionOutput ? vtkDoubleArray::SafeDownCast(rgba)->GetPointer(0) : nullptr,
    counts->GetPointer(0));

  this->Output->SetDimensions(width, height, 1);
  this->Output->GetPointData()->SetScalars(rgba);
  this->Output->GetPointData()->AddArray(counts);
  timer->StopTimer();
  this->LastRayCastTime = timer->GetElapsedTime();
  return 1;
}

//------------------------------------------------------------------------------
// Everything Render() needs is there and fits (an error for the first thing that does not);
// `depth` gets the opaque depth's values, if any.
bool vtkTetReferenceRenderer::CheckInputs(vtkVolumeProperty* property, const float*& depth)
{
  if (!this->Input)
  {
    vtkErrorMacro("No input.");
    return false;
  }
  if (this->Input->GetNumberOfPoints() == 0 || this->Input->GetNumberOfCells() == 0)
  {
    vtkErrorMacro("The input is empty.");
    return false;
  }
  if (!property)
  {
    vtkErrorMacro("No volume property.");
    return false;
  }
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
  double matrix[16];
  vtkMatrix4x4* m = this->Volume ? this->Volume->GetMatrix() : this->VolumeMatrix;
  vtkMatrix4x4::DeepCopy(matrix, m);
  // The one scalar the property takes from the selected array (the mapper's rule).
  int cellFlag = -1;
  vtkDataArray* array = vtkAbstractMapper::GetScalars(
    this->Input, this->ScalarMode, this->ArrayAccessMode, this->ArrayId, this->ArrayName, cellFlag);
  vtkNew<vtkTetScalarSelection> selection;
  selection->SetVectorMode(this->VectorMode);
  selection->SetVectorComponent(this->VectorComponent);
  if (array && !selection->Resolve(array->GetNumberOfComponents(), array->GetName(), property))
  {
    vtkErrorMacro("Not rendered: " << selection->GetErrorMessage() << ".");
    return false;
  }
  vtkTetReferenceMesh::ScalarSettings settings;
  settings.ScalarMode = this->ScalarMode;
  settings.ArrayAccessMode = this->ArrayAccessMode;
  settings.ArrayId = this->ArrayId;
  settings.ArrayName = this->ArrayName ? this->ArrayName : "";
  settings.ArrayNameSet = this->ArrayName != nullptr;
  settings.Magnitude = selection->GetMagnitude();
  settings.Component = selection->GetComponent();
  if (in.Mesh.IsPreparedFrom(this->Input, settings, matrix))
  {
    return true;
  }
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  std::string error;
  vtkIdType degenerate = 0;
  if (!in.Mesh.Prepare(this->Input, settings, matrix, degenerate, error))
  {
    vtkErrorMacro(<< error);
    return false;
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
  if (in.Property != property || in.PropertyMTime != property->GetMTime() ||
    !this->Integrator->IsInitialized())
  {
    if (!this->Integrator->Initialize(property))
    {
      vtkErrorMacro("The volume property cannot be integrated.");
      in.Property = nullptr;
      return false;
    }
    in.Property = property;
    in.PropertyMTime = property->GetMTime();
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::CompositeOverBackground(
  vtkImageData* rgba, const double background[3], vtkImageData* output)
{
  vtkTetReferenceCompositing::CompositeOverBackground(rgba, background, output);
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::ConvertToUnsignedChar(
  vtkImageData* rgba, const double background[3], vtkImageData* output)
{
  vtkTetReferenceCompositing::ConvertToUnsignedChar(rgba, background, output);
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::EmulateRayCastImageDisplay(
  vtkImageData* rgba, const double background[3], vtkImageData* output)
{
  vtkTetReferenceCompositing::EmulateRayCastImageDisplay(rgba, background, output);
}

//------------------------------------------------------------------------------
int vtkTetReferenceRenderer::CompareImages(vtkImageData* a, vtkImageData* b, double stats[3])
{
  return vtkTetReferenceCompositing::CompareImages(a, b, stats);
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Input: " << this->Input << "\n";
  os << indent << "ScalarMode: " << this->ScalarMode << "\n";
  os << indent << "ArrayAccessMode: " << this->ArrayAccessMode << "\n";
  os << indent << "ArrayId: " << this->ArrayId << "\n";
  os << indent << "ArrayName: " << (this->ArrayName ? this->ArrayName : "(none)") << "\n";
  os << indent << "VectorMode: " << this->VectorMode << "\n";
  os << indent << "VectorComponent: " << this->VectorComponent << "\n";
  os << indent << "VolumeProperty: " << this->VolumeProperty << "\n";
  os << indent << "Camera: " << this->Camera << "\n";
  os << indent << "ImageSize: " << this->ImageSize[0] << " x " << this->ImageSize[1] << "\n";
  os << indent << "Volume: " << this->Volume << "\n";
  os << indent << "OpaqueDepth: " << this->OpaqueDepth << "\n";
  os << indent << "ClippingPlanes: " << this->ClippingPlanes << "\n";
  os << indent << "BlendMode: " << this->BlendMode << "\n";
  os << indent << "AverageIPScalarRange: " << this->AverageIPScalarRange[0] << " "
     << this->AverageIPScalarRange[1] << "\n";
  os << indent << "SampleOffset: " << this->SampleOffset[0] << ", " << this->SampleOffset[1]
     << "\n";
  os << indent << "DoublePrecisionOutput: " << this->DoublePrecisionOutput << "\n";
  os << indent << "NumberOfTetrahedra: " << this->NumberOfTetrahedra << "\n";
  os << indent << "NumberOfDegenerateTetrahedra: " << this->NumberOfDegenerateTetrahedra << "\n";
  os << indent << "LastPreparationTime: " << this->LastPreparationTime << "\n";
  os << indent << "LastRayCastTime: " << this->LastRayCastTime << "\n";
  os << indent << "VolumeMatrix:\n";
  this->VolumeMatrix->PrintSelf(os, indent.GetNextIndent());
  os << indent << "Integrator:\n";
  this->Integrator->PrintSelf(os, indent.GetNextIndent());
}
