/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshPaperLayout.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetMeshPaperLayout.h"

#include "vtkFloatArray.h"
#include "vtkObjectFactory.h"
#include "vtkSMPTools.h"
#include "vtkTetMesh.h"
#include "vtkTimerLog.h"

#include <cmath>
#include <limits>
#include <sstream>

vtkStandardNewMacro(vtkTetMeshPaperLayout);

namespace
{
vtkFloatArray* NewArray(const char* name)
{
  vtkFloatArray* array = vtkFloatArray::New();
  array->SetName(name);
  array->SetNumberOfComponents(4);
  return array;
}
}

//------------------------------------------------------------------------------
vtkTetMeshPaperLayout::vtkTetMeshPaperLayout()
{
  const char* names[3] = { "Vertices", "FaceNormals", "NeighborsAndScalars" };
  for (const char* name : names)
  {
    ArrayInfo info;
    info.Array.TakeReference(NewArray(name));
    info.Kind = Texture2D;
    this->Arrays.push_back(info);
  }
  this->Boundary.Array.TakeReference(NewArray("BoundaryFaces"));
  this->Boundary.Kind = TextureBuffer;
}

//------------------------------------------------------------------------------
vtkTetMeshPaperLayout::~vtkTetMeshPaperLayout() = default;

//------------------------------------------------------------------------------
void vtkTetMeshPaperLayout::GetTetTexel(vtkIdType tet, int texel[2]) const
{
  const int w = this->PackedWidth > 0 ? this->PackedWidth : this->TextureWidth;
  texel[0] = static_cast<int>(tet % w);
  texel[1] = static_cast<int>(3 * (tet / w));
}

//------------------------------------------------------------------------------
bool vtkTetMeshPaperLayout::Build(vtkTetMesh* mesh)
{
  if (!this->CheckMesh(mesh))
  {
    return false;
  }
  // A vtkTimerLog event (recorded when logging is on) for the benchmark's phase times.
  vtkTimerLog::MarkStartEvent("vtkTetMeshPaperLayout: build");
  const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
  const vtkIdType width = this->TextureWidth;
  const vtkIdType rows = (numTets + width - 1) / width;
  const vtkIdType height = 3 * rows;
  if (width > this->MaximumTextureSize || height > this->MaximumTextureSize)
  {
    std::ostringstream text;
    text << "the paper layout of " << numTets << " tetrahedra needs three " << width << " x "
         << height << " textures, more than the maximum texture size " << this->MaximumTextureSize
         << " (use the compact layout)";
    this->Fail(text.str());
    return false;
  }
  // Texel coordinates are stored as floats: keep them exact.
  if (width > (1 << 24) || height > (1 << 24))
  {
    this->Fail("the paper layout cannot address textures larger than 2^24 texels a side");
    return false;
  }
  this->PackedWidth = static_cast<int>(width);
  const vtkIdType texels = width * height;
  for (ArrayInfo& info : this->Arrays)
  {
    info.Width = static_cast<int>(width);
    info.Array->SetNumberOfTuples(texels);
    // Padding after the last tetrahedron: zeros, never read.
    float* data = static_cast<vtkFloatArray*>(info.Array.Get())->GetPointer(0);
    for (vtkIdType t = numTets; t < rows * width; ++t)
    {
      for (int k = 0; k < 3; ++k)
      {
        float* texel = data + 4 * ((3 * (t / width) + k) * width + t % width);
        texel[0] = texel[1] = texel[2] = texel[3] = 0.0f;
      }
    }
  }

  // Neighbour texel coordinates: topology only.
  float* nb =
    static_cast<vtkFloatArray*>(this->Arrays[NeighborsAndScalarsArray].Array.Get())->GetPointer(0);
  const uint32_t* neighbors = mesh->GetTetNeighbors();
  vtkSMPTools::For(0, numTets, 8192,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType t = begin; t < end; ++t)
      {
        const vtkIdType base = 3 * (t / width) * width + t % width;
        for (int face = 0; face < 4; ++face)
        {
          const uint32_t word = neighbors[4 * t + face];
          float u = -1.0f, v = -1.0f;
          if (word != vtkTetMesh::NoNeighbor)
          {
            const vtkIdType n = static_cast<vtkIdType>(word >> 2);
            u = static_cast<float>(n % width);
            v = static_cast<float>(3 * (n / width));
          }
          // Faces 0, 1 in the first row, faces 2, 3 in the second.
          float* texel = nb + 4 * (base + (face / 2) * width);
          texel[2 * (face % 2)] = u;
          texel[2 * (face % 2) + 1] = v;
        }
      }
    });
  this->PackGeometry(mesh);
  this->PackScalars(mesh);
  this->PackBoundary(mesh);
  vtkTimerLog::MarkEndEvent("vtkTetMeshPaperLayout: build");
  this->Packed(mesh, UpdatedAll);
  return true;
}

//------------------------------------------------------------------------------
void vtkTetMeshPaperLayout::PackGeometry(vtkTetMesh* mesh)
{
  const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
  const vtkIdType width = this->PackedWidth;
  float* vertices =
    static_cast<vtkFloatArray*>(this->Arrays[VerticesArray].Array.Get())->GetPointer(0);
  float* normals =
    static_cast<vtkFloatArray*>(this->Arrays[FaceNormalsArray].Array.Get())->GetPointer(0);
  const double* points = mesh->GetPoints();
  const uint32_t* tetPoints = mesh->GetTetPoints();
  double shift[3];
  mesh->GetShift(shift);
  vtkSMPTools::For(0, numTets, 8192,
    [&](vtkIdType begin, vtkIdType end)
    {
      double n[12];
      for (vtkIdType t = begin; t < end; ++t)
      {
        const vtkIdType base = 3 * (t / width) * width + t % width;
        mesh->ComputeFaceNormalsFast(t, n, true);
        const double* p3 = points + 3 * static_cast<size_t>(tetPoints[4 * t + 3]);
        for (int k = 0; k < 3; ++k)
        {
          // Row k holds point k (and normal k) and the k-th coordinate of point 3 (normal 3).
          const double* pk = points + 3 * static_cast<size_t>(tetPoints[4 * t + k]);
          float* v = vertices + 4 * (base + k * width);
          v[0] = static_cast<float>(pk[0] - shift[0]);
          v[1] = static_cast<float>(pk[1] - shift[1]);
          v[2] = static_cast<float>(pk[2] - shift[2]);
          v[3] = static_cast<float>(p3[k] - shift[k]);
          float* nn = normals + 4 * (base + k * width);
          nn[0] = static_cast<float>(n[3 * k]);
          nn[1] = static_cast<float>(n[3 * k + 1]);
          nn[2] = static_cast<float>(n[3 * k + 2]);
          nn[3] = static_cast<float>(n[9 + k]);
        }
      }
    });
}

//------------------------------------------------------------------------------
void vtkTetMeshPaperLayout::PackScalars(vtkTetMesh* mesh)
{
  const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
  const double scalarShift = mesh->GetScalarShift();
  const double scalarScale = mesh->GetScalarScale();
  const vtkIdType width = this->PackedWidth;
  float* data =
    static_cast<vtkFloatArray*>(this->Arrays[NeighborsAndScalarsArray].Array.Get())->GetPointer(0);
  vtkSMPTools::For(0, numTets, 8192,
    [&](vtkIdType begin, vtkIdType end)
    {
      double gc[4];
      for (vtkIdType t = begin; t < end; ++t)
      {
        float* texel = data + 4 * ((3 * (t / width) + 2) * width + t % width);
        if (mesh->ComputeScalarGradientFast(t, gc))
        {
          gc[3] -= scalarShift; // see vtkTetMesh::GetScalarShift and GetScalarScale
          for (int k = 0; k < 4; ++k)
          {
            texel[k] = static_cast<float>(gc[k] * scalarScale);
          }
        }
        else
        {
          // Transparent: +infinity compares reliably in shaders, NaN may not.
          texel[0] = texel[1] = texel[2] = 0.0f;
          texel[3] = std::numeric_limits<float>::infinity();
        }
      }
    });
}

//------------------------------------------------------------------------------
void vtkTetMeshPaperLayout::PackBoundary(vtkTetMesh* mesh)
{
  const vtkIdType numFaces = mesh->GetNumberOfBoundaryFaces();
  const vtkIdType width = this->PackedWidth;
  auto* array = static_cast<vtkFloatArray*>(this->Boundary.Array.Get());
  array->SetNumberOfTuples(3 * numFaces);
  float* out = array->GetPointer(0);
  const uint32_t* faces = mesh->GetBoundaryFaces();
  const uint32_t* tetPoints = mesh->GetTetPoints();
  const double* points = mesh->GetPoints();
  double shift[3];
  mesh->GetShift(shift);
  vtkSMPTools::For(0, numFaces, 8192,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType f = begin; f < end; ++f)
      {
        const vtkIdType t = static_cast<vtkIdType>(faces[f] >> 2);
        const int i = static_cast<int>(faces[f] & 3u);
        const float extra[3] = { static_cast<float>(t % width), static_cast<float>(3 * (t / width)),
          static_cast<float>(i) };
        for (int k = 0; k < 3; ++k)
        {
          const double* p =
            points + 3 * static_cast<size_t>(tetPoints[4 * t + vtkTetMesh::FacePoints[i][k]]);
          float* texel = out + 4 * (3 * f + k);
          texel[0] = static_cast<float>(p[0] - shift[0]);
          texel[1] = static_cast<float>(p[1] - shift[1]);
          texel[2] = static_cast<float>(p[2] - shift[2]);
          texel[3] = extra[k];
        }
      }
    });
}

//------------------------------------------------------------------------------
bool vtkTetMeshPaperLayout::UpdatePoints(vtkTetMesh* mesh)
{
  if (!this->Valid || mesh != this->PackedMesh ||
    mesh->GetTopologyTime() != this->PackedTopologyTime || this->PackedWidth != this->TextureWidth)
  {
    return this->Build(mesh);
  }
  if (!this->CheckMesh(mesh))
  {
    return false;
  }
  // The gradients depend on the positions (and the shift) too.
  this->PackGeometry(mesh);
  this->PackScalars(mesh);
  this->PackBoundary(mesh);
  for (ArrayInfo& info : this->Arrays)
  {
    info.Array->Modified();
  }
  this->Boundary.Array->Modified();
  this->Packed(mesh, UpdatedPoints | UpdatedScalars);
  return true;
}

//------------------------------------------------------------------------------
bool vtkTetMeshPaperLayout::UpdateScalars(vtkTetMesh* mesh)
{
  if (!this->Valid || mesh != this->PackedMesh ||
    mesh->GetTopologyTime() != this->PackedTopologyTime || this->PackedWidth != this->TextureWidth)
  {
    return this->Build(mesh);
  }
  if (!this->CheckMesh(mesh))
  {
    return false;
  }
  this->PackScalars(mesh);
  this->Arrays[NeighborsAndScalarsArray].Array->Modified();
  this->Packed(mesh, UpdatedScalars);
  return true;
}

//------------------------------------------------------------------------------
void vtkTetMeshPaperLayout::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TextureWidth: " << this->TextureWidth << "\n";
}
