/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshBuildState.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetMeshBuildState.h"

#include "vtkAbstractArray.h"
#include "vtkCellArray.h"
#include "vtkDataSet.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkTetMeshValidationReport.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

namespace
{
template <typename T>
size_t Bytes(const vtkTetMeshVector<T>& v)
{
  return v.capacity() * sizeof(T);
}

template <typename T>
void Free(vtkTetMeshVector<T>& v)
{
  vtkTetMeshVector<T>().swap(v);
}

size_t Bytes(const vtkTetMeshWords& words)
{
  return words.capacity_bytes();
}

void Free(vtkTetMeshWords& words)
{
  words.free();
}
}

//------------------------------------------------------------------------------
vtkTetMeshBuildState::vtkTetMeshBuildState() = default;

//------------------------------------------------------------------------------
vtkTetMeshValidationReport* vtkTetMeshBuildState::GetReport()
{
  return this->Mesh->GetReport();
}

//------------------------------------------------------------------------------
vtkTetMeshBuildState::Stamp vtkTetMeshBuildState::MakeStamp(vtkObject* object, vtkIdType size)
{
  Stamp s;
  s.Object = object;
  s.MTime = object ? object->GetMTime() : 0;
  s.Size = size;
  return s;
}

//------------------------------------------------------------------------------
vtkTetMeshBuildState::Stamp vtkTetMeshBuildState::MakeStamp(vtkAbstractArray* array)
{
  return MakeStamp(array, array ? array->GetNumberOfValues() : 0);
}

//------------------------------------------------------------------------------
void vtkTetMeshBuildState::GetTopologyStamps(vtkDataSet* input, std::vector<Stamp>& stamps)
{
  stamps.clear();
  if (auto* ug = vtkUnstructuredGrid::SafeDownCast(input))
  {
    vtkCellArray* cells = ug->GetCells();
    stamps.push_back(MakeStamp(cells, cells ? cells->GetNumberOfCells() : 0));
    if (cells)
    {
      stamps.push_back(MakeStamp(cells->GetOffsetsArray()));
      stamps.push_back(MakeStamp(cells->GetConnectivityArray()));
    }
    stamps.push_back(MakeStamp(ug->GetCellTypesArray()));
    stamps.push_back(MakeStamp(ug->GetFaces()));
    stamps.push_back(MakeStamp(ug->GetFaceLocations()));
  }
  else if (input)
  {
    // No finer detail to go on: the data set's own time (not its arrays').
    Stamp s;
    s.Object = input;
    s.MTime = input->vtkObject::GetMTime();
    s.Size = input->GetNumberOfCells();
    stamps.push_back(s);
  }
}

//------------------------------------------------------------------------------
vtkTetMeshBuildState::Stamp vtkTetMeshBuildState::GetPointsStamp(vtkDataSet* input)
{
  auto* pointSet = vtkPointSet::SafeDownCast(input);
  if (pointSet && pointSet->GetPoints())
  {
    return MakeStamp(pointSet->GetPoints(), pointSet->GetPoints()->GetNumberOfPoints());
  }
  // Implicit points (image data, rectilinear grids) belong to the topology stamp.
  return Stamp();
}

//------------------------------------------------------------------------------
vtkIdType vtkTetMeshBuildState::GetScratchSize() const
{
  return static_cast<vtkIdType>(Bytes(this->FaceEntries) + Bytes(this->FaceCounts) +
    Bytes(this->BucketStarts) + Bytes(this->FaceSides) + Bytes(this->SortKeys) +
    Bytes(this->SortScratch) + Bytes(this->SortTetPoints) + Bytes(this->SortCellIds) +
    Bytes(this->Canonical));
}

//------------------------------------------------------------------------------
void vtkTetMeshBuildState::ReleaseScratch()
{
  Free(this->FaceEntries);
  Free(this->FaceCounts);
  Free(this->BucketStarts);
  Free(this->FaceSides);
  Free(this->SortKeys);
  Free(this->SortScratch);
  Free(this->SortTetPoints);
  Free(this->SortCellIds);
  Free(this->Canonical);
}

//------------------------------------------------------------------------------
int vtkTetMeshBuildState::NumberOfBlocks(vtkIdType work)
{
  const int threads = std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads());
  // A few blocks per thread balance the load; tiny inputs are not worth splitting.
  const vtkIdType byWork = std::max<vtkIdType>(1, work / 16384);
  return static_cast<int>(std::min<vtkIdType>({ byWork, 4 * threads, 64 }));
}
