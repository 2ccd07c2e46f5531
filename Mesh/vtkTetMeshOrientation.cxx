/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshOrientation.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetMeshOrientation.h"

#include "vtkIdTypeArray.h"
#include "vtkMath.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkTetMesh.h"
#include "vtkTetMeshBuildState.h"
#include "vtkTetMeshFaceMatching.h"
#include "vtkTetMeshValidationReport.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <vector>

//------------------------------------------------------------------------------
bool vtkTetMeshOrientation::Classify(vtkTetMeshBuildState& state, double tolerance, bool allowFlips)
{
  vtkTetMesh* mesh = state.Mesh;
  const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
  const double* p = mesh->Points.data();
  uint32_t* tp = mesh->TetPoints.data();
  // New flags start clear (a full build clears them first); a points-only rebuild keeps them.
  const size_t kept = mesh->TetFlags.size();
  mesh->TetFlags.resize(static_cast<size_t>(numTets));
  if (mesh->TetFlags.size() > kept)
  {
    vtkSMPTools::Fill(mesh->TetFlags.begin() + kept, mesh->TetFlags.end(), uint8_t(0));
  }
  uint8_t* flags = mesh->TetFlags.data();
  std::atomic<bool> needsFlip(false);
  // The longest edge comes with the pass (the mapper's pre-integration tables and their
  // choice need it at every build, a deforming mesh's included).
  vtkSMPThreadLocal<double> longest2(0.0);
  vtkSMPTools::For(0, numTets, 16384,
    [&](vtkIdType begin, vtkIdType end)
    {
      double& localLongest2 = longest2.Local();
      for (vtkIdType t = begin; t < end; ++t)
      {
        uint32_t* ids = tp + 4 * t;
        const double* p0 = p + 3 * static_cast<size_t>(ids[0]);
        const double* p1 = p + 3 * static_cast<size_t>(ids[1]);
        const double* p2 = p + 3 * static_cast<size_t>(ids[2]);
        const double* p3 = p + 3 * static_cast<size_t>(ids[3]);
        double e1[3], e2[3], e3[3], c[3];
        vtkMath::Subtract(p1, p0, e1);
        vtkMath::Subtract(p2, p0, e2);
        vtkMath::Subtract(p3, p0, e3);
        vtkMath::Cross(e2, e3, c);
        const double det = vtkMath::Dot(e1, c);
        double e4[3], e5[3], e6[3];
        vtkMath::Subtract(p2, p1, e4);
        vtkMath::Subtract(p3, p1, e5);
        vtkMath::Subtract(p3, p2, e6);
        const double l2 = std::max({ vtkMath::Dot(e1, e1), vtkMath::Dot(e2, e2),
          vtkMath::Dot(e3, e3), vtkMath::Dot(e4, e4), vtkMath::Dot(e5, e5), vtkMath::Dot(e6, e6) });
        localLongest2 = std::max(localLongest2, l2);
        const double l3 = l2 * std::sqrt(l2);
        uint8_t f = flags[t] & static_cast<uint8_t>(~vtkTetMesh::Degenerate);
        // 6|V| <= tol L^3; a tetrahedron with a repeated point has det exactly 0. The sign of a
        // degenerate tetrahedron's volume is rounding noise: it is never reoriented.
        const bool degenerate = std::abs(det) <= tolerance * l3;
        if (!allowFlips)
        {
          // What a full build of these positions would store: the input order unless the input
          // is inverted (and not degenerate). Anything else takes a full build.
          const bool swapped = (f & vtkTetMesh::Inverted) != 0;
          const bool wantSwap = (swapped ? -det : det) < 0.0 && !degenerate;
          if (wantSwap != swapped)
          {
            needsFlip = true;
          }
        }
        else
        {
          f &= static_cast<uint8_t>(~vtkTetMesh::Inverted);
          if (det < 0.0 && !degenerate)
          {
            std::swap(ids[2], ids[3]);
            f |= vtkTetMesh::Inverted;
          }
        }
        if (degenerate)
        {
          f |= vtkTetMesh::Degenerate;
        }
        flags[t] = f;
      }
    });
  if (needsFlip)
  {
    return false;
  }
  double l2 = 0.0;
  for (double v : longest2)
  {
    l2 = std::max(l2, v);
  }
  mesh->LongestEdge = std::sqrt(l2);
  CountClassified(state, allowFlips);
  return true;
}

//------------------------------------------------------------------------------
// Counts and the input cells of degenerate tetrahedra, into the report: in parallel, as every
// points-only rebuild of a deforming mesh does it (serial, 1.1M flags took about a millisecond
// of a 9 ms frame on the H100's host).
void vtkTetMeshOrientation::CountClassified(vtkTetMeshBuildState& state, bool countInverted)
{
  vtkTetMesh* mesh = state.Mesh;
  const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
  const uint8_t* flags = mesh->TetFlags.data();
  const uint32_t* cellIds = mesh->TetInputCellIds.data();
  vtkSMPThreadLocal<vtkIdType> invertedCounts(0);
  vtkSMPThreadLocal<std::vector<vtkIdType>> degenerateLists;
  vtkSMPTools::For(0, numTets, 65536,
    [&](vtkIdType begin, vtkIdType end)
    {
      vtkIdType& inverted = invertedCounts.Local();
      std::vector<vtkIdType>& degenerate = degenerateLists.Local();
      for (vtkIdType t = begin; t < end; ++t)
      {
        inverted += (flags[t] & vtkTetMesh::Inverted) ? 1 : 0;
        if (flags[t] & vtkTetMesh::Degenerate)
        {
          degenerate.push_back(cellIds[t]);
        }
      }
    });
  vtkIdType inverted = 0;
  for (vtkIdType count : invertedCounts)
  {
    inverted += count;
  }
  std::vector<vtkIdType> degenerateCells;
  for (const std::vector<vtkIdType>& list : degenerateLists)
  {
    degenerateCells.insert(degenerateCells.end(), list.begin(), list.end());
  }
  vtkTetMeshValidationReport* report = state.GetReport();
  report->SetNumberOfDegenerateTetrahedra(static_cast<vtkIdType>(degenerateCells.size()));
  std::sort(degenerateCells.begin(), degenerateCells.end());
  degenerateCells.erase(
    std::unique(degenerateCells.begin(), degenerateCells.end()), degenerateCells.end());
  vtkIdTypeArray* ids = report->GetDegenerateCellIds();
  ids->SetNumberOfValues(static_cast<vtkIdType>(degenerateCells.size()));
  std::copy(degenerateCells.begin(), degenerateCells.end(), ids->GetPointer(0));
  if (countInverted)
  {
    report->SetNumberOfInvertedTetrahedra(inverted);
  }
}

//------------------------------------------------------------------------------
// A degenerate tetrahedron's volume says nothing about its orientation, yet its faces are
// rasterised as boundary faces (culled by orientation) and a ray's exit is chosen by their
// outward normals: a flat tetrahedron on the boundary kept in its input order can face
// inwards and leave a hole. Its neighbours say which way it faces: across a shared face, two
// consistently oriented tetrahedra see opposite parities. So each degenerate tetrahedron
// takes the orientation of its first oriented neighbour (p2 <-> p3, which swaps faces 2 and
// 3), breadth first through chains of degenerate ones. Not counted as inverted: the
// validation report's inverted count is about the input's signed volumes.
void vtkTetMeshOrientation::OrientDegenerate(vtkTetMeshBuildState& state)
{
  constexpr uint32_t NoNeighbor = vtkTetMesh::NoNeighbor;
  vtkTetMesh* mesh = state.Mesh;
  const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
  const uint8_t* flags = mesh->TetFlags.data();
  std::vector<uint32_t> pending;
  for (vtkIdType t = 0; t < numTets; ++t)
  {
    if (flags[t] & vtkTetMesh::Degenerate)
    {
      pending.push_back(static_cast<uint32_t>(t));
    }
  }
  if (pending.empty())
  {
    return;
  }
  uint32_t* tp = mesh->TetPoints.data();
  uint32_t* neighbors = mesh->TetNeighbors.data();
  std::vector<bool> oriented(static_cast<size_t>(numTets), true);
  for (uint32_t t : pending)
  {
    oriented[t] = false;
  }
  // Rounds until no degenerate tetrahedron next to an oriented one is left (chains of
  // degenerate tetrahedra are short: each round orients the next link).
  bool progress = true;
  while (progress && !pending.empty())
  {
    progress = false;
    std::vector<uint32_t> left;
    for (uint32_t t : pending)
    {
      int reference = -1;
      for (int f = 0; f < 4 && reference < 0; ++f)
      {
        const uint32_t other = neighbors[4 * static_cast<size_t>(t) + f];
        if (other != NoNeighbor && oriented[other >> 2])
        {
          reference = f;
        }
      }
      if (reference < 0)
      {
        left.push_back(t);
        continue;
      }
      const uint32_t face = (t << 2) | static_cast<uint32_t>(reference);
      if (vtkTetMeshFaceMatching::FaceParity(tp, face) ==
        vtkTetMeshFaceMatching::FaceParity(tp, neighbors[face]))
      {
        uint32_t* ids = tp + 4 * static_cast<size_t>(t);
        std::swap(ids[2], ids[3]);
        uint32_t* own = neighbors + 4 * static_cast<size_t>(t);
        std::swap(own[2], own[3]);
        for (uint32_t f = 2; f < 4; ++f)
        {
          if (own[f] != NoNeighbor)
          {
            neighbors[own[f]] = (t << 2) | f;
          }
        }
      }
      oriented[t] = true;
      progress = true;
    }
    pending.swap(left);
  }
}
