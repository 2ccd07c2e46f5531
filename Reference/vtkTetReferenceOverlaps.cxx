/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetReferenceOverlaps.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetReferenceOverlaps.h"

#include <algorithm>
#include <array>
#include <utility>

namespace
{
// A face seen from one tetrahedron: its sorted point ids, the side the tetrahedron lies on, the
// tetrahedron.
struct SidedFace
{
  std::array<vtkIdType, 3> Ids;
  bool Side;
  size_t Tet;
};

// Outward faces of a positively oriented tetrahedron, face i opposite point i (design.md).
const int Outward[4][3] = { { 1, 2, 3 }, { 0, 3, 2 }, { 0, 1, 3 }, { 0, 2, 1 } };
}

//------------------------------------------------------------------------------
std::vector<unsigned char> vtkTetReferenceOverlaps::Find(const std::vector<vtkIdType>& tets)
{
  const size_t numTets = tets.size() / 4;
  std::vector<SidedFace> faces;
  faces.reserve(4 * numTets);
  for (size_t t = 0; t < numTets; ++t)
  {
    for (const int* f : Outward)
    {
      std::array<vtkIdType, 3> ids = { tets[4 * t + f[0]], tets[4 * t + f[1]],
        tets[4 * t + f[2]] };
      // The side is the parity of the outward order: sort by swaps and count them.
      bool odd = false;
      for (int pass = 0; pass < 2; ++pass)
      {
        for (int k = 0; k + 1 < 3 - pass; ++k)
        {
          if (ids[k + 1] < ids[k])
          {
            std::swap(ids[k], ids[k + 1]);
            odd = !odd;
          }
        }
      }
      if (ids[0] != ids[1] && ids[1] != ids[2])
      {
        faces.push_back({ ids, odd, t });
      }
    }
  }
  std::sort(faces.begin(), faces.end(),
    [](const SidedFace& a, const SidedFace& b)
    { return a.Ids != b.Ids ? a.Ids < b.Ids : a.Tet < b.Tet; });
  std::vector<unsigned char> leftOut(numTets, 0);
  for (size_t run = 0; run < faces.size();)
  {
    size_t end = run + 1;
    while (end < faces.size() && faces[end].Ids == faces[run].Ids)
    {
      ++end;
    }
    // In input order: the first on each side stays, the others on that side are left out.
    bool seen[2] = { false, false };
    for (size_t k = run; k < end; ++k)
    {
      bool& side = seen[faces[k].Side ? 1 : 0];
      if (side)
      {
        leftOut[faces[k].Tet] = 1;
      }
      side = true;
    }
    run = end;
  }
  return leftOut;
}
