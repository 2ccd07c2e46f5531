/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastEmptySpace.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastEmptySpace.h"

#include "vtkSMPTools.h"
#include "vtkTetMesh.h"
#include "vtkTiledRayCastTransferFunction.h"
#include "vtkTimerLog.h"

#include <algorithm>
#include <bitset>
#include <cmath>
#include <limits>

namespace
{
// Whether the closed interval [lo, hi] meets one of the sorted, disjoint closed intervals.
bool Meets(const std::vector<std::pair<double, double>>& support, double lo, double hi)
{
  // The first interval that does not end before lo.
  auto it = std::lower_bound(support.begin(), support.end(), lo,
    [](const std::pair<double, double>& interval, double value)
    { return interval.second < value; });
  return it != support.end() && it->first <= hi;
}
}

//------------------------------------------------------------------------------
std::vector<std::pair<double, double>> vtkTiledRayCastEmptySpace::ComputeSupport(
  vtkTiledRayCastTransferFunction* tf)
{
  std::vector<std::pair<double, double>> support;
  const int n = tf->GetNumberOfNodes();
  const double infinity = std::numeric_limits<double>::infinity();
  auto add = [&support](double lo, double hi)
  {
    if (!support.empty() && lo <= support.back().second)
    {
      support.back().second = std::max(support.back().second, hi);
    }
    else
    {
      support.emplace_back(lo, hi);
    }
  };
  if (n == 0)
  {
    return support;
  }
  // Constant below the first node and above the last; linear between nodes, so a piece is zero
  // throughout exactly when it is zero at both ends.
  if (tf->GetNodeAttenuation(0) > 0)
  {
    add(-infinity, tf->GetNodeScalar(0));
  }
  for (int i = 0; i + 1 < n; ++i)
  {
    if (tf->GetNodeAttenuation(i) > 0 || tf->GetNodeAttenuation(i + 1) > 0)
    {
      add(tf->GetNodeScalar(i), tf->GetNodeScalar(i + 1));
    }
  }
  if (tf->GetNodeAttenuation(n - 1) > 0)
  {
    add(tf->GetNodeScalar(n - 1), infinity);
  }
  return support;
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastEmptySpace::Update(vtkTetMesh* mesh, vtkTiledRayCastTransferFunction* tf)
{
  // Without scalars there is nothing to classify by.
  const bool enabled = tf != nullptr && mesh->HasScalars();
  const vtkMTimeType topology = mesh->GetTopologyTime();
  const vtkMTimeType scalars = mesh->GetScalarsTime();
  const vtkMTimeType tfTime = tf ? tf->GetMTime() : 0;
  this->BuildTime = 0;
  if (mesh == this->Mesh && enabled == this->Enabled && topology == this->MeshTopologyTime &&
    scalars == this->MeshScalarsTime && (!enabled || tfTime == this->TransferFunctionTime))
  {
    return false;
  }
  this->Mesh = mesh;
  this->Enabled = enabled;
  this->MeshTopologyTime = topology;
  this->MeshScalarsTime = scalars;
  this->TransferFunctionTime = tfTime;

  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  const bool skipped = this->Skips;
  const vtkIdType visible = this->NumberOfVisible;
  this->VisibleBits.clear();
  this->EntryFaces.clear();
  this->Skips = false;
  this->NumberOfVisible = mesh->GetNumberOfTetrahedra();
  if (enabled)
  {
    this->Classify(mesh, ComputeSupport(tf));
    this->Skips = this->NumberOfVisible < mesh->GetNumberOfTetrahedra();
    if (this->Skips)
    {
      this->ListEntryFaces(mesh);
    }
    else
    {
      this->VisibleBits.clear();
    }
  }
  timer->StopTimer();
  this->BuildTime = timer->GetElapsedTime();
  // The caller uploads again only when the bits or faces can have changed.
  return this->Skips || skipped != this->Skips || visible != this->NumberOfVisible;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastEmptySpace::Classify(
  vtkTetMesh* mesh, const std::vector<std::pair<double, double>>& support)
{
  const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
  const uint32_t* tetPoints = mesh->GetTetPoints();
  const double* pointScalars = mesh->GetPointScalars();
  const double* cellScalars = mesh->GetCellScalars();
  const uint8_t* flags = mesh->GetTetFlags();
  double range[2];
  mesh->GetScalarRange(range);
  const double shift = vtkTetMesh::ComputeScalarShift(range);
  // The shaders evaluate the scalar along a segment in float, from scalars shifted by `shift`:
  // a segment's ends may stray from the tetrahedron's range by a few roundings of the shifted
  // values. Widened by that, the test never leaves out a tetrahedron the shaders would see.
  const double spread = std::max(std::abs(range[0] - shift), std::abs(range[1] - shift));
  const double margin = 64.0 * std::numeric_limits<float>::epsilon() * spread;

  const vtkIdType numWords = (numTets + 31) / 32;
  this->VisibleBits.assign(static_cast<size_t>(numWords), 0u);
  std::vector<vtkIdType> counts(static_cast<size_t>(numWords), 0);
  // One word (32 tetrahedra) per task item: no two threads write the same word.
  vtkSMPTools::For(0, numWords, 1024,
    [&](vtkIdType firstWord, vtkIdType endWord)
    {
      for (vtkIdType w = firstWord; w < endWord; ++w)
      {
        uint32_t bits = 0;
        const vtkIdType end = std::min<vtkIdType>(32 * w + 32, numTets);
        for (vtkIdType t = 32 * w; t < end; ++t)
        {
          // Overlapping tetrahedra are left out of the rendering (no ray enters them); one that
          // touches a non-finite scalar is crossed without integration.
          if (flags[t] & (vtkTetMesh::Overlapping | vtkTetMesh::NonFiniteScalars))
          {
            continue;
          }
          double lo, hi;
          if (cellScalars)
          {
            lo = hi = cellScalars[t];
          }
          else if (pointScalars)
          {
            const uint32_t* ids = tetPoints + 4 * t;
            const double s0 = pointScalars[ids[0]], s1 = pointScalars[ids[1]];
            const double s2 = pointScalars[ids[2]], s3 = pointScalars[ids[3]];
            lo = std::min(std::min(s0, s1), std::min(s2, s3));
            hi = std::max(std::max(s0, s1), std::max(s2, s3));
          }
          else
          {
            continue;
          }
          if (std::isfinite(lo) && std::isfinite(hi) && Meets(support, lo - margin, hi + margin))
          {
            bits |= 1u << (t & 31);
          }
        }
        this->VisibleBits[static_cast<size_t>(w)] = bits;
        counts[static_cast<size_t>(w)] = static_cast<vtkIdType>(std::bitset<32>(bits).count());
      }
    });
  this->NumberOfVisible = 0;
  for (vtkIdType c : counts)
  {
    this->NumberOfVisible += c;
  }
}

//------------------------------------------------------------------------------
void vtkTiledRayCastEmptySpace::ListEntryFaces(vtkTetMesh* mesh)
{
  const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
  const uint32_t* neighbors = mesh->GetTetNeighbors();
  const std::vector<uint32_t>& bits = this->VisibleBits;
  auto visible = [&bits](uint32_t t) { return (bits[t >> 5] >> (t & 31)) & 1u; };
  for (vtkIdType t = 0; t < numTets; ++t)
  {
    if (!visible(static_cast<uint32_t>(t)))
    {
      continue;
    }
    for (int f = 0; f < 4; ++f)
    {
      const uint32_t word = neighbors[4 * t + f];
      if (word == vtkTetMesh::NoNeighbor || !visible(word >> 2))
      {
        this->EntryFaces.push_back(static_cast<uint32_t>(t << 2) | static_cast<uint32_t>(f));
      }
    }
  }
}
