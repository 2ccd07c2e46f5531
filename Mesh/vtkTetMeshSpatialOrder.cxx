/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshSpatialOrder.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetMeshSpatialOrder.h"

#include "vtkSMPTools.h"
#include "vtkTetMesh.h"
#include "vtkTetMeshBuildState.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace
{
//------------------------------------------------------------------------------
// Spreads the low 11 bits of v so that they occupy every third bit.
inline uint64_t SpreadBits3(uint64_t v)
{
  v &= 0x7ffu;
  v = (v | (v << 16)) & 0x0000ff0000ffull;
  v = (v | (v << 8)) & 0x00f00f00f00full;
  v = (v | (v << 4)) & 0x0c30c30c30c3ull;
  v = (v | (v << 2)) & 0x249249249249ull;
  return v;
}

// The 33-bit Morton code of positions in the mesh's bounds, 11 bits per axis.
class MortonGrid
{
public:
  explicit MortonGrid(const double bounds[6])
  {
    for (int c = 0; c < 3; ++c)
    {
      this->Origin[c] = bounds[2 * c];
      const double extent = bounds[2 * c + 1] - bounds[2 * c];
      this->Scale[c] = extent > 0.0 ? 2047.0 / extent : 0.0;
    }
  }
  uint64_t Code(const double x[3]) const
  {
    uint64_t code = 0;
    for (int c = 0; c < 3; ++c)
    {
      const double q = std::min(2047.0, std::max(0.0, (x[c] - this->Origin[c]) * this->Scale[c]));
      code |= SpreadBits3(static_cast<uint64_t>(q)) << c;
    }
    return code;
  }

private:
  double Origin[3];
  double Scale[3];
};
}

//------------------------------------------------------------------------------
void vtkTetMeshSpatialOrder::Sort(vtkTetMeshBuildState& state)
{
  ComputeKeys(state);
  SortKeys(state, 30);
  vtkTetMesh* mesh = state.Mesh;
  const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
  const uint32_t* tp = mesh->TetPoints.data();
  const vtkTetMeshVector<uint64_t>& keys = state.SortKeys;
  vtkTetMeshWords& tetPoints = state.SortTetPoints;
  vtkTetMeshVector<uint32_t>& cellIds = state.SortCellIds;
  tetPoints.resize(mesh->TetPoints.size());
  cellIds.resize(mesh->TetInputCellIds.size());
  vtkSMPTools::For(0, numTets, 16384,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType t = begin; t < end; ++t)
      {
        const size_t old = static_cast<size_t>(keys[t] & ((uint64_t(1) << 30) - 1));
        std::copy(tp + 4 * old, tp + 4 * old + 4, tetPoints.begin() + 4 * t);
        cellIds[t] = mesh->TetInputCellIds[old];
      }
    });
  mesh->TetPoints.swap(tetPoints);
  mesh->TetInputCellIds.swap(cellIds);
}

//------------------------------------------------------------------------------
// One 64-bit key per tetrahedron: 33 bits of Morton code above the 30-bit tetrahedron id.
void vtkTetMeshSpatialOrder::ComputeKeys(vtkTetMeshBuildState& state)
{
  vtkTetMesh* mesh = state.Mesh;
  const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
  const double* p = mesh->Points.data();
  const uint32_t* tp = mesh->TetPoints.data();
  const MortonGrid grid(mesh->Bounds);
  MakeKeys(state, numTets, 30,
    [&](vtkIdType t)
    {
      double centroid[3];
      for (int c = 0; c < 3; ++c)
      {
        centroid[c] = 0.25 *
          (p[3 * tp[4 * t] + c] + p[3 * tp[4 * t + 1] + c] + p[3 * tp[4 * t + 2] + c] +
            p[3 * tp[4 * t + 3] + c]);
      }
      return grid.Code(centroid);
    });
}

//------------------------------------------------------------------------------
void vtkTetMeshSpatialOrder::SortPoints(vtkTetMeshBuildState& state)
{
  vtkTetMesh* mesh = state.Mesh;
  const vtkIdType numPoints = mesh->GetNumberOfPoints();
  if (numPoints >= (vtkIdType(1) << 31))
  {
    return;
  }
  // One key per point: 33 bits of Morton code of its position above its 31-bit id.
  const double* p = mesh->Points.data();
  const MortonGrid grid(mesh->Bounds);
  MakeKeys(state, numPoints, 31, [&](vtkIdType i) { return grid.Code(p + 3 * i); });
  SortKeys(state, 31);
  const vtkTetMeshVector<uint64_t>& keys = state.SortKeys;

  // The input id of each new point, the new id of each input point, then the points and the
  // tetrahedra's ids in the new numbering.
  mesh->PointInputIds.resize(static_cast<size_t>(numPoints));
  vtkTetMeshVector<uint32_t>& newIds = state.SortCellIds; // scratch of the right type
  newIds.resize(static_cast<size_t>(numPoints));
  uint32_t* inputIds = mesh->PointInputIds.data();
  vtkSMPTools::For(0, numPoints, 65536,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        const uint32_t old = static_cast<uint32_t>(keys[i] & ((uint64_t(1) << 31) - 1));
        inputIds[i] = old;
        newIds[old] = static_cast<uint32_t>(i);
      }
    });
  // The input's coordinates in its own order, put in the new one.
  ApplyPointOrder(mesh, mesh->Points, 3);
  uint32_t* tp = mesh->TetPoints.data();
  vtkSMPTools::For(0, static_cast<vtkIdType>(mesh->TetPoints.size()), 65536,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType k = begin; k < end; ++k)
      {
        tp[k] = newIds[tp[k]];
      }
    });
}

//------------------------------------------------------------------------------
// Three stable counting passes of 11 bits over the code above the `idBits` bits of the id
// (least significant first): linear, and ties stay in input order. Bits above 63 are none.
void vtkTetMeshSpatialOrder::SortKeys(vtkTetMeshBuildState& state, int idBits)
{
  vtkTetMeshVector<uint64_t>& keys = state.SortKeys;
  vtkTetMeshVector<uint64_t>& scratch = state.SortScratch;
  scratch.resize(keys.size());
  // Each pass in parallel: every block of keys counts its digits, the counts' prefix sums in
  // (digit, block) order give each block where its keys of each digit go, and the blocks
  // scatter at once. Stable, and the same result as one thread's (one thread sorting a billion
  // keys is a long serial step of a huge build).
  const vtkIdType n = static_cast<vtkIdType>(keys.size());
  const int blocks = vtkTetMeshBuildState::NumberOfBlocks(n);
  std::vector<size_t> position(static_cast<size_t>(blocks) * 2048);
  for (int shift = idBits; shift < std::min(64, idBits + 33); shift += 11)
  {
    std::fill(position.begin(), position.end(), 0);
    vtkTetMeshBuildState::ForBlocks(n, blocks,
      [&](int b, vtkIdType begin, vtkIdType end)
      {
        size_t* count = position.data() + static_cast<size_t>(b) * 2048;
        for (vtkIdType i = begin; i < end; ++i)
        {
          ++count[(keys[i] >> shift) & 2047];
        }
      });
    size_t running = 0;
    for (size_t digit = 0; digit < 2048; ++digit)
    {
      for (int b = 0; b < blocks; ++b)
      {
        size_t& slot = position[static_cast<size_t>(b) * 2048 + digit];
        const size_t count = slot;
        slot = running;
        running += count;
      }
    }
    vtkTetMeshBuildState::ForBlocks(n, blocks,
      [&](int b, vtkIdType begin, vtkIdType end)
      {
        size_t* next = position.data() + static_cast<size_t>(b) * 2048;
        for (vtkIdType i = begin; i < end; ++i)
        {
          scratch[next[(keys[i] >> shift) & 2047]++] = keys[i];
        }
      });
    keys.swap(scratch);
  }
}
