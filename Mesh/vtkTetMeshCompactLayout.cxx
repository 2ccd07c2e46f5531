/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshCompactLayout.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetMeshCompactLayout.h"
#include "vtkTetMeshHugePages.h"

#include "vtkFloatArray.h"
#include "vtkObjectFactory.h"
#include "vtkSMPTools.h"
#include "vtkTetMesh.h"
#include "vtkTimerLog.h"
#include "vtkTypeUInt32Array.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

vtkStandardNewMacro(vtkTetMeshCompactLayout);

namespace
{
template <typename ArrayT>
ArrayT* NewArray(const char* name, int components)
{
  ArrayT* array = ArrayT::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  return array;
}

inline float FiniteOrInfinity(double value)
{
  // Non-finite scalars become +infinity: shaders compare it reliably (NaN may not).
  return std::isfinite(value) ? static_cast<float>(value) : std::numeric_limits<float>::infinity();
}
}

//------------------------------------------------------------------------------
vtkTetMeshCompactLayout::vtkTetMeshCompactLayout()
{
  ArrayInfo info;
  info.Kind = TextureBuffer;
  info.Array.TakeReference(NewArray<vtkTypeUInt32Array>("TetPoints", 4));
  this->Arrays.push_back(info);
  info.Array.TakeReference(NewArray<vtkTypeUInt32Array>("TetNeighbors", 4));
  this->Arrays.push_back(info);
  info.Array.TakeReference(NewArray<vtkFloatArray>("Points", 4));
  this->Arrays.push_back(info);
  this->CellScalars.Kind = TextureBuffer;
  this->CellScalars.Array.TakeReference(NewArray<vtkFloatArray>("TetScalars", 1));
  this->Boundary.Kind = TextureBuffer;
  this->Boundary.Array.TakeReference(NewArray<vtkTypeUInt32Array>("BoundaryFaces", 4));
}

//------------------------------------------------------------------------------
vtkTetMeshCompactLayout::~vtkTetMeshCompactLayout() = default;

//------------------------------------------------------------------------------
bool vtkTetMeshCompactLayout::Build(vtkTetMesh* mesh)
{
  if (!this->CheckMesh(mesh))
  {
    return false;
  }
  // A vtkTimerLog event (recorded when logging is on) for the benchmark's phase times.
  vtkTimerLog::MarkStartEvent("vtkTetMeshCompactLayout: build");
  const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
  const vtkIdType numPoints = mesh->GetNumberOfPoints();
  const vtkIdType numFaces = mesh->GetNumberOfBoundaryFaces();
  // Arrays larger than one texture buffer are split over several, up to the limit.
  const vtkIdType largest = std::max({ numTets, numPoints, numFaces });
  const vtkIdType bufferSize = this->GetTextureBufferSize();
  const vtkIdType buffers = (largest + bufferSize - 1) / bufferSize;
  if (buffers > this->MaximumTextureBuffersPerArray)
  {
    std::ostringstream text;
    text << "the compact layout of " << numTets << " tetrahedra, " << numPoints << " points and "
         << numFaces << " boundary faces needs " << buffers << " texture buffers of " << bufferSize
         << " texels for an array of " << largest << " texels, more than the "
         << this->MaximumTextureBuffersPerArray
         << " allowed per array (maximum texture buffer size " << this->MaximumTextureBufferSize
         << " texels)";
    this->Fail(text.str());
    return false;
  }

  // The tetrahedra's point ids and neighbour words are the mesh's own arrays, shared, not
  // copied (32 bytes a tetrahedron).
  this->Arrays.resize(3);
  this->Arrays[TetPointsArray].Array = mesh->GetTetPointsArray();
  this->Arrays[TetNeighborsArray].Array = mesh->GetTetNeighborsArray();
  if (mesh->GetHasCellScalars())
  {
    this->Arrays.push_back(this->CellScalars);
  }
  this->PackPoints(mesh);
  this->PackCellScalars(mesh);

  // Boundary faces: three point ids in outward order and the face word.
  auto* boundary = static_cast<vtkTypeUInt32Array*>(this->Boundary.Array.Get());
  boundary->SetNumberOfTuples(numFaces);
  uint32_t* out = boundary->GetPointer(0);
  const uint32_t* faces = mesh->GetBoundaryFaces();
  const uint32_t* tp = mesh->GetTetPoints();
  vtkSMPTools::For(0, numFaces, 16384,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType f = begin; f < end; ++f)
      {
        const uint32_t word = faces[f];
        const uint32_t* ids = tp + 4 * static_cast<size_t>(word >> 2);
        const int* fp = vtkTetMesh::FacePoints[word & 3u];
        out[4 * f] = ids[fp[0]];
        out[4 * f + 1] = ids[fp[1]];
        out[4 * f + 2] = ids[fp[2]];
        out[4 * f + 3] = word;
      }
    });
  vtkTimerLog::MarkEndEvent("vtkTetMeshCompactLayout: build");
  this->Packed(mesh, UpdatedAll);
  return true;
}

//------------------------------------------------------------------------------
void vtkTetMeshCompactLayout::PackPoints(vtkTetMesh* mesh)
{
  const vtkIdType numPoints = mesh->GetNumberOfPoints();
  auto* array = static_cast<vtkFloatArray*>(this->Arrays[PointsArray].Array.Get());
  array->SetNumberOfTuples(numPoints);
  float* out = array->GetPointer(0);
  vtkTetMeshHugePages::Advise(out, 16 * static_cast<size_t>(numPoints));
  const double* p = mesh->GetPoints();
  const double* s = mesh->GetPointScalars();
  double shift[3];
  mesh->GetShift(shift);
  const double scalarShift = mesh->GetScalarShift();
  const double scalarScale = mesh->GetScalarScale();
  vtkSMPTools::For(0, numPoints, 16384,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        out[4 * i] = static_cast<float>(p[3 * i] - shift[0]);
        out[4 * i + 1] = static_cast<float>(p[3 * i + 1] - shift[1]);
        out[4 * i + 2] = static_cast<float>(p[3 * i + 2] - shift[2]);
        out[4 * i + 3] = s ? FiniteOrInfinity((s[i] - scalarShift) * scalarScale) : 0.0f;
      }
    });
}

//------------------------------------------------------------------------------
void vtkTetMeshCompactLayout::PackCellScalars(vtkTetMesh* mesh)
{
  auto* array = static_cast<vtkFloatArray*>(this->CellScalars.Array.Get());
  const double* s = mesh->GetCellScalars();
  if (!s)
  {
    array->SetNumberOfTuples(0);
    return;
  }
  const double scalarShift = mesh->GetScalarShift();
  const double scalarScale = mesh->GetScalarScale();
  const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
  array->SetNumberOfTuples(numTets);
  float* out = array->GetPointer(0);
  vtkTetMeshHugePages::Advise(out, sizeof(float) * static_cast<size_t>(numTets));
  vtkSMPTools::For(0, numTets, 16384,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType t = begin; t < end; ++t)
      {
        out[t] = FiniteOrInfinity((s[t] - scalarShift) * scalarScale);
      }
    });
}

//------------------------------------------------------------------------------
bool vtkTetMeshCompactLayout::NeedsBuild(vtkTetMesh* mesh)
{
  // A switch between point and cell scalars changes the set of arrays.
  return !this->Valid || mesh != this->PackedMesh ||
    mesh->GetTopologyTime() != this->PackedTopologyTime ||
    mesh->GetHasCellScalars() != (this->GetNumberOfArrays() > TetScalarsArray);
}

//------------------------------------------------------------------------------
bool vtkTetMeshCompactLayout::UpdatePoints(vtkTetMesh* mesh)
{
  if (!mesh || this->NeedsBuild(mesh))
  {
    return this->Build(mesh);
  }
  if (!this->CheckMesh(mesh))
  {
    return false;
  }
  // The point texels carry the point scalars as well; point ids and neighbours, the boundary
  // included, do not move.
  this->PackPoints(mesh);
  this->Arrays[PointsArray].Array->Modified();
  if (mesh->GetHasCellScalars())
  {
    this->PackCellScalars(mesh);
    this->CellScalars.Array->Modified();
  }
  this->Packed(mesh, UpdatedPoints | UpdatedScalars);
  return true;
}

//------------------------------------------------------------------------------
bool vtkTetMeshCompactLayout::UpdateScalars(vtkTetMesh* mesh)
{
  if (!mesh || this->NeedsBuild(mesh))
  {
    return this->Build(mesh);
  }
  if (!this->CheckMesh(mesh))
  {
    return false;
  }
  if (mesh->GetHasCellScalars())
  {
    this->PackCellScalars(mesh);
    this->CellScalars.Array->Modified();
  }
  else
  {
    // Only the w component changes; rewriting whole texels is as cheap and keeps one path.
    this->PackPoints(mesh);
    this->Arrays[PointsArray].Array->Modified();
  }
  this->Packed(mesh, UpdatedScalars);
  return true;
}

//------------------------------------------------------------------------------
void vtkTetMeshCompactLayout::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
