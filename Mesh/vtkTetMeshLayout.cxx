/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshLayout.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetMeshLayout.h"

#include "vtkDataArray.h"
#include "vtkTetMesh.h"
#include "vtkTetMeshValidationReport.h"

#include <algorithm>

//------------------------------------------------------------------------------
vtkTetMeshLayout::vtkTetMeshLayout() = default;

//------------------------------------------------------------------------------
vtkTetMeshLayout::~vtkTetMeshLayout() = default;

//------------------------------------------------------------------------------
bool vtkTetMeshLayout::UpdatePoints(vtkTetMesh* mesh)
{
  return this->Build(mesh);
}

//------------------------------------------------------------------------------
bool vtkTetMeshLayout::UpdateScalars(vtkTetMesh* mesh)
{
  return this->Build(mesh);
}

//------------------------------------------------------------------------------
bool vtkTetMeshLayout::Update(vtkTetMesh* mesh)
{
  if (!mesh)
  {
    this->Fail("no mesh");
    return false;
  }
  if (!this->Valid && mesh == this->FailedMesh && mesh->GetMTime() == this->FailedMeshTime &&
    this->GetMTime() <= this->FailedTime.GetMTime())
  {
    // The same failure as last time: say it once, not every frame.
    this->LastUpdate = UpdatedNothing;
    return false;
  }
  if (!this->Valid || mesh != this->PackedMesh ||
    mesh->GetTopologyTime() != this->PackedTopologyTime ||
    this->GetMTime() > this->PackedTime.GetMTime())
  {
    return this->Build(mesh);
  }
  int done = UpdatedNothing;
  bool ok = true;
  if (mesh->GetPointsTime() != this->PackedPointsTime)
  {
    ok = this->UpdatePoints(mesh);
    done |= this->LastUpdate;
  }
  if (ok && mesh->GetScalarsTime() != this->PackedScalarsTime)
  {
    ok = this->UpdateScalars(mesh);
    done |= this->LastUpdate;
  }
  this->LastUpdate = done;
  return ok;
}

//------------------------------------------------------------------------------
bool vtkTetMeshLayout::CheckMesh(vtkTetMesh* mesh)
{
  this->FailedMesh = mesh;
  this->FailedMeshTime = mesh ? mesh->GetMTime() : 0;
  if (!mesh)
  {
    this->Fail("no mesh");
    return false;
  }
  if (!mesh->GetReport()->GetUsable())
  {
    this->Fail(std::string("the mesh is unusable: ") + mesh->GetReport()->GetErrorMessage());
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTetMeshLayout::Fail(const std::string& message)
{
  this->ErrorMessage = message;
  this->Valid = false;
  this->PackedMesh = nullptr;
  this->LastUpdate = UpdatedNothing;
  vtkErrorMacro(<< message << ".");
  this->Modified();
  this->FailedTime.Modified();
}

//------------------------------------------------------------------------------
void vtkTetMeshLayout::Packed(vtkTetMesh* mesh, int what)
{
  this->ErrorMessage.clear();
  this->Valid = true;
  this->PackedMesh = mesh;
  this->PackedTopologyTime = mesh->GetTopologyTime();
  if (what & UpdatedPoints)
  {
    this->PackedPointsTime = mesh->GetPointsTime();
    mesh->GetShift(this->Shift);
  }
  if (what & UpdatedScalars)
  {
    this->PackedScalarsTime = mesh->GetScalarsTime();
  }
  this->NumberOfTetrahedra = mesh->GetNumberOfTetrahedra();
  this->LastUpdate = what;
  // After a full build every array is new; partial updates mark what they rewrote.
  if (what == UpdatedAll)
  {
    for (ArrayInfo& info : this->Arrays)
    {
      info.Array->Modified();
    }
    if (this->Boundary.Array)
    {
      this->Boundary.Array->Modified();
    }
  }
  this->Modified();
  this->PackedTime.Modified();
}

//------------------------------------------------------------------------------
vtkDataArray* vtkTetMeshLayout::GetArray(int index)
{
  return index >= 0 && index < this->GetNumberOfArrays() ? this->Arrays[index].Array.Get()
                                                         : nullptr;
}

//------------------------------------------------------------------------------
const char* vtkTetMeshLayout::GetArrayName(int index)
{
  vtkDataArray* array = this->GetArray(index);
  return array ? array->GetName() : nullptr;
}

//------------------------------------------------------------------------------
int vtkTetMeshLayout::GetArrayKind(int index)
{
  return index >= 0 && index < this->GetNumberOfArrays() ? this->Arrays[index].Kind : -1;
}

//------------------------------------------------------------------------------
void vtkTetMeshLayout::GetArrayTextureSize(int index, int size[2])
{
  size[0] = size[1] = 0;
  vtkDataArray* array = this->GetArray(index);
  if (!array)
  {
    return;
  }
  const ArrayInfo& info = this->Arrays[index];
  const vtkIdType texels = array->GetNumberOfTuples();
  if (info.Kind == Texture2D && info.Width > 0)
  {
    size[0] = info.Width;
    size[1] = static_cast<int>(texels / info.Width);
  }
  else
  {
    size[0] = static_cast<int>(texels);
    size[1] = 1;
  }
}

//------------------------------------------------------------------------------
int vtkTetMeshLayout::GetTextureBufferShift() const
{
  int shift = 0;
  while (shift < 62 && (vtkIdType(2) << shift) <= this->MaximumTextureBufferSize)
  {
    ++shift;
  }
  return shift;
}

//------------------------------------------------------------------------------
int vtkTetMeshLayout::GetNumberOfTextureBuffers(int index)
{
  vtkDataArray* array = this->GetArray(index);
  if (!array)
  {
    return 0;
  }
  if (this->Arrays[index].Kind != TextureBuffer)
  {
    return 1;
  }
  const vtkIdType size = this->GetTextureBufferSize();
  return static_cast<int>(std::max<vtkIdType>(1, (array->GetNumberOfTuples() + size - 1) / size));
}

//------------------------------------------------------------------------------
vtkDataArray* vtkTetMeshLayout::GetBoundaryArray()
{
  return this->Boundary.Array;
}

//------------------------------------------------------------------------------
vtkIdType vtkTetMeshLayout::GetNumberOfBytes()
{
  vtkIdType bytes = 0;
  for (const ArrayInfo& info : this->Arrays)
  {
    bytes += info.Array->GetNumberOfValues() * info.Array->GetDataTypeSize();
  }
  return bytes;
}

//------------------------------------------------------------------------------
vtkIdType vtkTetMeshLayout::GetNumberOfBoundaryBytes()
{
  vtkDataArray* array = this->Boundary.Array;
  return array ? array->GetNumberOfValues() * array->GetDataTypeSize() : 0;
}

//------------------------------------------------------------------------------
vtkIdType vtkTetMeshLayout::GetNumberOfBytesWithBoundary()
{
  return this->GetNumberOfBytes() + this->GetNumberOfBoundaryBytes();
}

//------------------------------------------------------------------------------
double vtkTetMeshLayout::GetBytesPerTet()
{
  return this->NumberOfTetrahedra > 0
    ? static_cast<double>(this->GetNumberOfBytes()) / this->NumberOfTetrahedra
    : 0.0;
}

//------------------------------------------------------------------------------
double vtkTetMeshLayout::GetBytesPerTetWithBoundary()
{
  return this->NumberOfTetrahedra > 0
    ? static_cast<double>(this->GetNumberOfBytesWithBoundary()) / this->NumberOfTetrahedra
    : 0.0;
}

//------------------------------------------------------------------------------
void vtkTetMeshLayout::GetShift(double shift[3]) const
{
  shift[0] = this->Shift[0];
  shift[1] = this->Shift[1];
  shift[2] = this->Shift[2];
}

//------------------------------------------------------------------------------
void vtkTetMeshLayout::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Valid: " << (this->Valid ? "true" : "false") << "\n";
  if (!this->ErrorMessage.empty())
  {
    os << indent << "ErrorMessage: " << this->ErrorMessage << "\n";
  }
  os << indent << "NumberOfTetrahedra: " << this->NumberOfTetrahedra << "\n";
  os << indent << "MaximumTextureSize: " << this->MaximumTextureSize << "\n";
  os << indent << "MaximumTextureBufferSize: " << this->MaximumTextureBufferSize << "\n";
  os << indent << "MaximumTextureBuffersPerArray: " << this->MaximumTextureBuffersPerArray << "\n";
  os << indent << "Shift: (" << this->Shift[0] << ", " << this->Shift[1] << ", " << this->Shift[2]
     << ")\n";
  os << indent << "LastUpdate: " << this->LastUpdate << "\n";
  for (int i = 0; i < this->GetNumberOfArrays(); ++i)
  {
    int size[2];
    this->GetArrayTextureSize(i, size);
    os << indent << "Array " << i << ": " << this->GetArrayName(i) << " ("
       << (this->Arrays[i].Kind == Texture2D ? "2D texture " : "texture buffer ") << size[0]
       << " x " << size[1] << ", " << this->Arrays[i].Array->GetNumberOfComponents()
       << " components, " << this->GetNumberOfTextureBuffers(i) << " texture buffer(s))\n";
  }
  os << indent << "Bytes: " << this->GetNumberOfBytes() << " (with boundary "
     << this->GetNumberOfBytesWithBoundary() << ")\n";
}
