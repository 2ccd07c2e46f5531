/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshBlockMerger.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetMeshBlockMerger.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCompositeDataIterator.h"
#include "vtkDataArray.h"
#include "vtkDataObjectTree.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkTetScalarSelection.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridBase.h"

#include <array>
#include <cmath>
#include <cstring>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

vtkStandardNewMacro(vtkTetMeshBlockMerger);

namespace
{
// A non-empty block and how its scalars are read.
struct Block
{
  vtkDataSet* Data;
  vtkMTimeType MTime;
  vtkDataArray* Scalars;
  bool Magnitude;
  int Component;
  bool operator==(const Block& o) const
  {
    return Data == o.Data && MTime == o.MTime && Scalars == o.Scalars && Magnitude == o.Magnitude &&
      Component == o.Component;
  }
};

// The coordinates and scalar of a point, bit for bit (-0 as +0), as a merging key.
using PointKey = std::array<uint64_t, 4>;
struct PointKeyHash
{
  size_t operator()(const PointKey& k) const
  {
    uint64_t h = 0x9e3779b97f4a7c15ull;
    for (uint64_t v : k)
    {
      h ^= v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    }
    return static_cast<size_t>(h);
  }
};
uint64_t Bits(double v)
{
  v += 0.0; // -0 -> +0
  uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}
}

//------------------------------------------------------------------------------
class vtkTetMeshBlockMerger::vtkInternals
{
public:
  vtkNew<vtkUnstructuredGrid> Output;
  bool Valid = false;
  vtkDataObjectTree* Input = nullptr;
  vtkMTimeType InputMTime = 0;
  std::vector<Block> Blocks;
  int CellFlag = -1;
  std::string Error;

  // The leaves of `input` that hold cells, with their scalars; false with Error on a block
  // that cannot be merged.
  bool Collect(vtkTetMeshBlockMerger* self, vtkDataObjectTree* input, vtkVolumeProperty* property,
    std::vector<Block>& blocks, int& cellFlag);
  // Append the blocks into Output.
  void Build(const std::vector<Block>& blocks, int cellFlag, vtkIdType& shared);
};

//------------------------------------------------------------------------------
bool vtkTetMeshBlockMerger::vtkInternals::Collect(vtkTetMeshBlockMerger* self,
  vtkDataObjectTree* input, vtkVolumeProperty* property, std::vector<Block>& blocks, int& cellFlag)
{
  vtkSmartPointer<vtkCompositeDataIterator> it;
  it.TakeReference(input->NewIterator());
  it->SkipEmptyNodesOff();
  vtkIdType index = 0;
  self->NumberOfBlocks = self->NumberOfEmptyBlocks = 0;
  cellFlag = -1;
  vtkTetScalarSelection* selection = self->ScalarSelection;
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem(), ++index)
  {
    ++self->NumberOfBlocks;
    vtkDataObject* leaf = it->GetCurrentDataObject();
    std::ostringstream text;
    text << "block " << index;
    if (leaf && !vtkUnstructuredGridBase::SafeDownCast(leaf))
    {
      text << " is a " << leaf->GetClassName()
           << ": a composite input is rendered from its unstructured grids only";
      this->Error = text.str();
      return false;
    }
    vtkDataSet* data = vtkDataSet::SafeDownCast(leaf);
    if (!data || data->GetNumberOfCells() == 0)
    {
      ++self->NumberOfEmptyBlocks;
      continue;
    }
    int flag = -1;
    vtkDataArray* scalars = selection->GetScalars(data, flag);
    if (!scalars || (flag != 0 && flag != 1))
    {
      text << " has no point or cell scalars to render (check the scalar mode and the selected "
              "array)";
      this->Error = text.str();
      return false;
    }
    if (cellFlag >= 0 && flag != cellFlag)
    {
      text << " has " << (flag ? "cell" : "point") << " scalars where the blocks before it have "
           << (cellFlag ? "cell" : "point") << " scalars";
      this->Error = text.str();
      return false;
    }
    cellFlag = flag;
    if (!selection->Resolve(scalars->GetNumberOfComponents(), scalars->GetName(), property))
    {
      text << ": " << selection->GetErrorMessage();
      this->Error = text.str();
      return false;
    }
    blocks.push_back(
      { data, data->GetMTime(), scalars, selection->GetMagnitude(), selection->GetComponent() });
  }
  if (blocks.empty())
  {
    this->Error = "the composite input has no block with cells (" +
      std::to_string(self->NumberOfBlocks) + " blocks, all empty)";
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTetMeshBlockMerger::vtkInternals::Build(
  const std::vector<Block>& blocks, int cellFlag, vtkIdType& shared)
{
  vtkUnstructuredGrid* out = this->Output;
  out->Initialize();
  vtkIdType numPoints = 0, numCells = 0;
  for (const Block& b : blocks)
  {
    numPoints += b.Data->GetNumberOfPoints();
    numCells += b.Data->GetNumberOfCells();
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->Allocate(numPoints);
  out->Allocate(numCells);
  vtkNew<vtkDoubleArray> values;
  values->SetName(blocks[0].Scalars->GetName() ? blocks[0].Scalars->GetName() : "scalars");
  values->Allocate(cellFlag ? numCells : numPoints);

  // Points of earlier blocks, by coordinates and (point) scalar.
  std::unordered_map<PointKey, vtkIdType, PointKeyHash> earlier;
  std::vector<double> reduced;
  std::vector<vtkIdType> map;
  vtkNew<vtkIdList> ids;
  shared = 0;
  for (const Block& b : blocks)
  {
    reduced.resize(static_cast<size_t>(b.Scalars->GetNumberOfTuples()));
    vtkTetScalarSelection::Extract(b.Scalars, b.Magnitude, b.Component, reduced.data());
    const vtkIdType n = b.Data->GetNumberOfPoints();
    map.resize(static_cast<size_t>(n));
    std::vector<std::pair<PointKey, vtkIdType>> added;
    for (vtkIdType i = 0; i < n; ++i)
    {
      double p[3];
      b.Data->GetPoint(i, p);
      const double s = cellFlag ? 0.0 : reduced[i];
      const bool finite =
        std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]) && std::isfinite(s);
      const PointKey key = { Bits(p[0]), Bits(p[1]), Bits(p[2]), Bits(s) };
      auto found = finite ? earlier.find(key) : earlier.end();
      if (found != earlier.end())
      {
        map[i] = found->second;
        ++shared;
        continue;
      }
      map[i] = points->InsertNextPoint(p);
      if (!cellFlag)
      {
        values->InsertNextValue(s);
      }
      if (finite)
      {
        added.emplace_back(key, map[i]);
      }
    }
    for (const auto& entry : added)
    {
      earlier.emplace(entry.first, entry.second); // the first of equal points within a block
    }
    for (vtkIdType c = 0; c < b.Data->GetNumberOfCells(); ++c)
    {
      b.Data->GetCellPoints(c, ids);
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      {
        const vtkIdType id = ids->GetId(k);
        ids->SetId(k, id >= 0 && id < n ? map[id] : -1);
      }
      out->InsertNextCell(b.Data->GetCellType(c), ids);
      if (cellFlag)
      {
        values->InsertNextValue(reduced[c]);
      }
    }
  }
  out->SetPoints(points);
  if (cellFlag)
  {
    out->GetCellData()->SetScalars(values);
  }
  else
  {
    out->GetPointData()->SetScalars(values);
  }
}

//------------------------------------------------------------------------------
vtkTetMeshBlockMerger::vtkTetMeshBlockMerger()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkTetMeshBlockMerger::~vtkTetMeshBlockMerger() = default;

//------------------------------------------------------------------------------
vtkUnstructuredGrid* vtkTetMeshBlockMerger::Merge(
  vtkDataObjectTree* input, vtkVolumeProperty* property)
{
  vtkInternals& in = *this->Internals;
  in.Error.clear();
  if (!input)
  {
    in.Error = "no input";
    in.Valid = false;
    return nullptr;
  }
  std::vector<Block> blocks;
  int cellFlag = -1;
  if (!in.Collect(this, input, property, blocks, cellFlag))
  {
    in.Valid = false;
    return nullptr;
  }
  const bool fresh = in.Valid && in.Input == input && in.InputMTime == input->GetMTime() &&
    in.CellFlag == cellFlag && in.Blocks == blocks;
  if (!fresh)
  {
    // Polyhedra carry face streams of point ids, which the merge does not renumber.
    for (size_t k = 0; k < blocks.size(); ++k)
    {
      for (vtkIdType c = 0; c < blocks[k].Data->GetNumberOfCells(); ++c)
      {
        if (blocks[k].Data->GetCellType(c) == VTK_POLYHEDRON)
        {
          in.Error = "the block with cells number " + std::to_string(k) +
            " holds polyhedra, which a composite input cannot hold (merge it into one grid first)";
          in.Valid = false;
          return nullptr;
        }
      }
    }
    in.Build(blocks, cellFlag, this->NumberOfSharedPoints);
    in.Input = input;
    in.InputMTime = input->GetMTime();
    in.Blocks = blocks;
    in.CellFlag = cellFlag;
    in.Valid = true;
  }
  return in.Output;
}

//------------------------------------------------------------------------------
const char* vtkTetMeshBlockMerger::GetErrorMessage()
{
  return this->Internals->Error.c_str();
}

//------------------------------------------------------------------------------
void vtkTetMeshBlockMerger::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ScalarSelection:\n";
  this->ScalarSelection->PrintSelf(os, indent.GetNextIndent());
  os << indent << "NumberOfBlocks: " << this->NumberOfBlocks << "\n";
  os << indent << "NumberOfEmptyBlocks: " << this->NumberOfEmptyBlocks << "\n";
  os << indent << "NumberOfSharedPoints: " << this->NumberOfSharedPoints << "\n";
  os << indent << "ErrorMessage: " << this->Internals->Error << "\n";
}
