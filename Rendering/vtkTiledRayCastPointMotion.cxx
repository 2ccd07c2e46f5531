/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastPointMotion.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastPointMotion.h"

#include "vtkDataArray.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTetMesh.h"
#include "vtkTetMeshCompactLayout.h"
#include "vtkTiledRayCastComputeShader.h"
#include "vtkTiledRayCastMeshTextures.h"
#include "vtk_glew.h"

#include "vtkTiledRayCastPointMotionCS.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace
{
// The Motion block of vtkTiledRayCastPointMotionCS.glsl (std430).
struct MotionBlock
{
  double Shift[3];
  double Tolerance;
  uint32_t Changed;
  uint32_t NonFinite;
  uint32_t Longest2; // float bits
  uint32_t Padding;
};
static_assert(sizeof(MotionBlock) == 48, "the shader's Motion block");
constexpr size_t FindingsOffset = offsetof(MotionBlock, Changed);
constexpr size_t FindingsBytes = 3 * sizeof(uint32_t);
constexpr unsigned int GroupSize = 256; // the shader's local_size_x
}

//------------------------------------------------------------------------------
vtkTiledRayCastPointMotion::vtkTiledRayCastPointMotion() = default;

//------------------------------------------------------------------------------
vtkTiledRayCastPointMotion::~vtkTiledRayCastPointMotion() = default;

//------------------------------------------------------------------------------
bool vtkTiledRayCastPointMotion::BuildPrograms(bool doubles)
{
  std::string defines = doubles ? "#define TRC_INPUT_DOUBLE\n" : "";
  defines += "#define TRC_FLAG_INVERTED " + std::to_string(vtkTetMesh::Inverted) + "u\n";
  defines += "#define TRC_FLAG_DEGENERATE " + std::to_string(vtkTetMesh::Degenerate) + "u\n";
  std::string write = vtkTiledRayCastPointMotionCS;
  vtkShaderProgram::Substitute(write, "//TRC::Defines", defines, false);
  std::string check = vtkTiledRayCastPointMotionCS;
  vtkShaderProgram::Substitute(
    check, "//TRC::Defines", defines + "#define TRC_MOTION_CHECK\n", false);
  if (this->Write->GetHandle() && this->Write->GetSource() == write)
  {
    return true;
  }
  if (!this->Check->Build(check))
  {
    this->Reason = "Internal error: " + std::string(this->Check->GetError());
    return false;
  }
  if (!this->Write->Build(write))
  {
    this->Reason = "Internal error: " + std::string(this->Write->GetError());
    this->Check->ReleaseProgram();
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
// What only a full build changes: the point order (with the topology) and the flags (at every
// CPU build, a points-only one included).
bool vtkTiledRayCastPointMotion::UploadMeshTables(vtkTetMesh* mesh, vtkIdType& uploaded)
{
  const bool sameMesh = this->TablesMesh == mesh;
  this->TablesMesh = mesh;
  const uint32_t* order = mesh->GetPointInputIds();
  if (order && (!sameMesh || mesh->GetTopologyTime() != this->OrderTime))
  {
    const size_t bytes = 4 * static_cast<size_t>(mesh->GetNumberOfPoints());
    if ((this->PointOrder.GetSize() != bytes && !this->PointOrder.Allocate(bytes)))
    {
      return false;
    }
    this->PointOrder.Write(0, bytes, order);
    this->OrderTime = mesh->GetTopologyTime();
    uploaded += static_cast<vtkIdType>(bytes);
  }
  if (!sameMesh || mesh->GetMTime() != this->FlagsTime)
  {
    // Four flags to a word, padded to whole words.
    const size_t tets = static_cast<size_t>(mesh->GetNumberOfTetrahedra());
    const size_t bytes = 4 * ((tets + 3) / 4);
    if (this->Flags.GetSize() != bytes && !this->Flags.Allocate(bytes))
    {
      return false;
    }
    std::vector<uint8_t> padded(bytes, 0);
    std::memcpy(padded.data(), mesh->GetTetFlags(), tets);
    this->Flags.Write(0, bytes, padded.data());
    this->FlagsTime = mesh->GetMTime();
    uploaded += static_cast<vtkIdType>(bytes);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastPointMotion::Dispatch(
  vtkTiledRayCastComputeShader* program, vtkIdType invocations)
{
  const vtkIdType groups = (invocations + GroupSize - 1) / GroupSize;
  const vtkIdType x = std::min<vtkIdType>(groups, 65535);
  const vtkIdType y = x > 0 ? (groups + x - 1) / x : 0;
  program->Dispatch(static_cast<unsigned int>(x), static_cast<unsigned int>(y));
}

//------------------------------------------------------------------------------
vtkTiledRayCastPointMotion::Result vtkTiledRayCastPointMotion::Move(vtkOpenGLRenderWindow* window,
  vtkDataArray* coordinates, vtkTetMesh* mesh, vtkTetMeshLayout* layout,
  const vtkTiledRayCastMeshTextures& textures, double tolerance, const double shift[3],
  double& longestEdge, vtkIdType& uploaded)
{
  this->Reason.clear();
  const int type = coordinates ? coordinates->GetDataType() : VTK_VOID;
  const vtkIdType numPoints = mesh->GetNumberOfPoints();
  const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
  if ((type != VTK_FLOAT && type != VTK_DOUBLE) || coordinates->GetNumberOfComponents() != 3 ||
    coordinates->GetNumberOfTuples() != numPoints || !mesh->GetTetFlags())
  {
    this->Reason = "the input's points are not 3 floats or doubles each";
    return Unavailable;
  }
  // Every buffer a pass binds must fit one shader storage block.
  const size_t maxBinding = vtkTiledRayCastStorageBuffer::GetMaximumBindingSize();
  const size_t partTexels = static_cast<size_t>(layout->GetTextureBufferSize());
  const size_t inputBytes = static_cast<size_t>(coordinates->GetDataTypeSize()) * 3 * numPoints;
  const size_t largestPart =
    16 * std::min(partTexels, static_cast<size_t>(std::max(numPoints, numTets)));
  if (std::max({ inputBytes, largestPart, 4 * static_cast<size_t>(numPoints),
        static_cast<size_t>(numTets) }) > maxBinding)
  {
    this->Reason = "the mesh's buffers are larger than a shader storage block";
    return Unavailable;
  }
  if (!this->BuildPrograms(type == VTK_DOUBLE))
  {
    return Unavailable;
  }

  // The input's coordinates as they are; the tables that only a CPU build changes.
  vtkIdType sent = 0;
  if ((this->InputPoints.GetSize() != inputBytes && !this->InputPoints.Allocate(inputBytes)) ||
    !this->UploadMeshTables(mesh, sent))
  {
    this->Reason = "the GPU is out of memory";
    this->ReleaseGraphicsResources();
    return Unavailable;
  }
  this->InputPoints.Write(0, inputBytes, coordinates->GetVoidPointer(0));
  sent += static_cast<vtkIdType>(inputBytes);
  MotionBlock findings = {};
  std::copy(shift, shift + 3, findings.Shift);
  findings.Tolerance = tolerance;
  if ((this->Findings.GetSize() != sizeof(MotionBlock) &&
        !this->Findings.Allocate(sizeof(MotionBlock))) ||
    (this->FindingsRead.GetSize() != FindingsBytes &&
      !this->FindingsRead.AllocateForReading(FindingsBytes)))
  {
    this->Reason = "the GPU is out of memory";
    this->ReleaseGraphicsResources();
    return Unavailable;
  }
  this->Findings.Write(0, sizeof(MotionBlock), &findings);
  this->InputPoints.BindBase(0);
  if (mesh->GetPointInputIds())
  {
    this->PointOrder.BindBase(1);
  }
  this->Findings.BindBase(2);
  const int ordered = mesh->GetPointInputIds() ? 1 : 0;

  // 1. Classify, check, measure; read the findings back.
  vtkTiledRayCastComputeShader* check = this->Check;
  check->Use(window);
  check->SetUniformi("in_ordered", ordered);
  this->Flags.BindBase(4);
  const int tetParts = layout->GetNumberOfTextureBuffers(vtkTetMeshCompactLayout::TetPointsArray);
  for (int k = 0; k < tetParts; ++k)
  {
    const vtkIdType first = static_cast<vtkIdType>(k) * static_cast<vtkIdType>(partTexels);
    const vtkIdType count =
      std::min<vtkIdType>(static_cast<vtkIdType>(partTexels), numTets - first);
    const vtkIdType points = k == 0 ? numPoints : 0;
    vtkTiledRayCastStorageBuffer::BindBufferBase(
      3, textures.GetBufferHandle(vtkTetMeshCompactLayout::TetPointsArray, k));
    check->SetUniformi("in_firstTet", static_cast<int>(first));
    check->SetUniformi("in_tetCount", static_cast<int>(count));
    check->SetUniformi("in_pointCount", static_cast<int>(points));
    this->Dispatch(check, std::max(count, points));
  }
  vtkTiledRayCastComputeShader::Barrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  this->Findings.CopyTo(this->FindingsRead, FindingsOffset, 0, FindingsBytes);
  this->FindingsRead.MarkWritten();
  this->FindingsRead.IsWritten(true);
  uint32_t read[3] = { 0, 0, 0 };
  this->FindingsRead.Read(0, FindingsBytes, read);
  uploaded += sent;
  if (read[0] > 0 || read[1] > 0)
  {
    this->Reason = read[1] > 0 ? "coordinates are not finite" : "tetrahedra changed orientation";
    return NeedsRebuild;
  }
  float longest2 = 0.0f;
  std::memcpy(&longest2, &read[2], sizeof(float));
  longestEdge = std::sqrt(static_cast<double>(longest2));

  // 2. The point texels, part by part.
  vtkTiledRayCastComputeShader* write = this->Write;
  write->Use(window);
  write->SetUniformi("in_ordered", ordered);
  const int pointParts = layout->GetNumberOfTextureBuffers(vtkTetMeshCompactLayout::PointsArray);
  for (int k = 0; k < pointParts; ++k)
  {
    const vtkIdType first = static_cast<vtkIdType>(k) * static_cast<vtkIdType>(partTexels);
    const vtkIdType count =
      std::min<vtkIdType>(static_cast<vtkIdType>(partTexels), numPoints - first);
    vtkTiledRayCastStorageBuffer::BindBufferBase(
      3, textures.GetBufferHandle(vtkTetMeshCompactLayout::PointsArray, k));
    write->SetUniformi("in_firstPoint", static_cast<int>(first));
    write->SetUniformi("in_pointCount", static_cast<int>(count));
    this->Dispatch(write, count);
  }
  vtkTiledRayCastComputeShader::Barrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  for (unsigned int binding = 0; binding < 5; ++binding)
  {
    vtkTiledRayCastStorageBuffer::BindBufferBase(binding, 0);
  }
  return Moved;
}

//------------------------------------------------------------------------------
vtkIdType vtkTiledRayCastPointMotion::GetBytes() const
{
  return static_cast<vtkIdType>(this->InputPoints.GetSize() + this->PointOrder.GetSize() +
    this->Flags.GetSize() + this->Findings.GetSize() + this->FindingsRead.GetSize());
}

//------------------------------------------------------------------------------
void vtkTiledRayCastPointMotion::ReleaseGraphicsResources()
{
  this->Check->ReleaseProgram();
  this->Write->ReleaseProgram();
  this->InputPoints.ReleaseGraphicsResources();
  this->PointOrder.ReleaseGraphicsResources();
  this->Flags.ReleaseGraphicsResources();
  this->Findings.ReleaseGraphicsResources();
  this->FindingsRead.ReleaseGraphicsResources();
  this->OrderTime = 0;
  this->FlagsTime = 0;
  this->TablesMesh = nullptr;
}
