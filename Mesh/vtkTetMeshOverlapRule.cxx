/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshOverlapRule.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetMeshOverlapRule.h"

#include "vtkTetMesh.h"

#include <algorithm>

//------------------------------------------------------------------------------
void vtkTetMeshOverlapRule::Resolve(
  const Entry* entries, size_t m, uint32_t link[2], std::vector<uint32_t>& leftOut)
{
  constexpr uint32_t None = vtkTetMesh::NoNeighbor;
  link[0] = link[1] = None;
  const Entry* kept[2] = { nullptr, nullptr };
  const Entry* degenerate[2] = { nullptr, nullptr };
  auto earlier = [](const Entry* a, const Entry* b)
  {
    return a->InputCell != b->InputCell ? a->InputCell < b->InputCell : a->Face < b->Face;
  };
  for (size_t k = 0; k < m; ++k)
  {
    const Entry* e = entries + k;
    if (e->Degenerate)
    {
      const int slot = degenerate[0] ? 1 : 0;
      if (!degenerate[slot])
      {
        degenerate[slot] = e;
      }
      continue;
    }
    const Entry*& side = kept[e->Side ? 1 : 0];
    if (!side)
    {
      side = e;
    }
    else if (earlier(e, side))
    {
      leftOut.push_back(side->Face >> 2);
      side = e;
    }
    else
    {
      leftOut.push_back(e->Face >> 2);
    }
  }
  // The kept pair; else a kept one with a degenerate one; else two degenerate ones.
  const Entry* a = kept[0] ? kept[0] : kept[1];
  const Entry* b = kept[0] ? kept[1] : nullptr;
  if (!b)
  {
    b = a ? degenerate[0] : degenerate[1];
    a = a ? a : degenerate[0];
  }
  if (a && b)
  {
    link[0] = a->Face;
    link[1] = b->Face;
  }
}

//------------------------------------------------------------------------------
vtkIdType vtkTetMeshOverlapRule::Apply(
  std::vector<uint32_t>& leftOut, uint32_t* neighbors, uint8_t* flags, uint8_t flag)
{
  std::sort(leftOut.begin(), leftOut.end());
  leftOut.erase(std::unique(leftOut.begin(), leftOut.end()), leftOut.end());
  for (uint32_t t : leftOut)
  {
    flags[t] |= flag;
    for (uint32_t i = 0; i < 4; ++i)
    {
      uint32_t& across = neighbors[(t << 2) | i];
      if (across != vtkTetMesh::NoNeighbor)
      {
        neighbors[across] = vtkTetMesh::NoNeighbor;
        across = vtkTetMesh::NoNeighbor;
      }
    }
  }
  return static_cast<vtkIdType>(leftOut.size());
}
