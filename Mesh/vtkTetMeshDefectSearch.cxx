/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshDefectSearch.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetMeshDefectSearch.h"

#include "vtkMath.h"
#include "vtkSMPTools.h"
#include "vtkTetMesh.h"
#include "vtkTetMeshBuildState.h"
#include "vtkTetMeshValidationReport.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <numeric>
#include <utility>
#include <vector>

namespace
{
constexpr uint32_t NoNeighbor = vtkTetMesh::NoNeighbor;

//------------------------------------------------------------------------------
// 2D separating-axis test for two triangles (strict: touching is not overlapping).
bool TrianglesOverlap2D(const double a[3][2], const double b[3][2], double eps)
{
  const double(*tris[2])[2] = { a, b };
  for (int t = 0; t < 2; ++t)
  {
    const double(*tri)[2] = tris[t];
    for (int e = 0; e < 3; ++e)
    {
      const double* p = tri[e];
      const double* q = tri[(e + 1) % 3];
      const double axis[2] = { q[1] - p[1], p[0] - q[0] };
      double minA = VTK_DOUBLE_MAX, maxA = -VTK_DOUBLE_MAX;
      double minB = VTK_DOUBLE_MAX, maxB = -VTK_DOUBLE_MAX;
      for (int k = 0; k < 3; ++k)
      {
        const double pa = a[k][0] * axis[0] + a[k][1] * axis[1];
        const double pb = b[k][0] * axis[0] + b[k][1] * axis[1];
        minA = std::min(minA, pa);
        maxA = std::max(maxA, pa);
        minB = std::min(minB, pb);
        maxB = std::max(maxB, pb);
      }
      const double scale = eps * std::sqrt(axis[0] * axis[0] + axis[1] * axis[1]);
      if (maxA <= minB + scale || maxB <= minA + scale)
      {
        return false;
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
// The boundary faces of a mesh, their points and coordinates, and the crack test between two
// of them.
class BoundaryFaceGeometry
{
public:
  const double* Points;
  const uint32_t* TetPoints;

  uint32_t FacePoint(uint32_t face, int k) const
  {
    return this
      ->TetPoints[4 * static_cast<size_t>(face >> 2) + vtkTetMesh::FacePoints[face & 3u][k]];
  }

  // Whether faces f and g face each other in the same plane with overlapping interiors.
  bool Overlap(uint32_t f, uint32_t g) const
  {
    double a[3][3], b[3][3];
    for (int k = 0; k < 3; ++k)
    {
      const double* pf = this->Points + 3 * static_cast<size_t>(this->FacePoint(f, k));
      const double* pg = this->Points + 3 * static_cast<size_t>(this->FacePoint(g, k));
      std::copy(pf, pf + 3, a[k]);
      std::copy(pg, pg + 3, b[k]);
    }
    double ab[3], ac[3], nf[3], ng[3];
    vtkMath::Subtract(a[1], a[0], ab);
    vtkMath::Subtract(a[2], a[0], ac);
    vtkMath::Cross(ab, ac, nf);
    vtkMath::Subtract(b[1], b[0], ab);
    vtkMath::Subtract(b[2], b[0], ac);
    vtkMath::Cross(ab, ac, ng);
    const double lf = std::sqrt(vtkMath::Dot(nf, nf));
    const double lg = std::sqrt(vtkMath::Dot(ng, ng));
    if (lf == 0.0 || lg == 0.0)
    {
      return false;
    }
    for (int c = 0; c < 3; ++c)
    {
      nf[c] /= lf;
      ng[c] /= lg;
    }
    // Facing each other: the two sides of a seam.
    if (vtkMath::Dot(nf, ng) > -0.99)
    {
      return false;
    }
    double size = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      double e[3];
      vtkMath::Subtract(a[(k + 1) % 3], a[k], e);
      size = std::max(size, std::sqrt(vtkMath::Dot(e, e)));
    }
    // In the same plane, to a small fraction of the face size.
    for (int k = 0; k < 3; ++k)
    {
      double d[3];
      vtkMath::Subtract(b[k], a[0], d);
      if (std::abs(vtkMath::Dot(d, nf)) > 1e-3 * size)
      {
        return false;
      }
    }
    return InteriorsOverlap(a, b, nf, size);
  }

private:
  // Overlapping interiors, in the plane of the first face (normal nf).
  static bool InteriorsOverlap(
    const double a[3][3], const double b[3][3], const double nf[3], double size)
  {
    double u[3], w[3];
    vtkMath::Subtract(a[1], a[0], u);
    const double lu = std::sqrt(vtkMath::Dot(u, u));
    for (int c = 0; c < 3; ++c)
    {
      u[c] /= lu;
    }
    vtkMath::Cross(nf, u, w);
    double a2[3][2], b2[3][2];
    for (int k = 0; k < 3; ++k)
    {
      double d[3];
      vtkMath::Subtract(a[k], a[0], d);
      a2[k][0] = vtkMath::Dot(d, u);
      a2[k][1] = vtkMath::Dot(d, w);
      vtkMath::Subtract(b[k], a[0], d);
      b2[k][0] = vtkMath::Dot(d, u);
      b2[k][1] = vtkMath::Dot(d, w);
    }
    return TrianglesOverlap2D(a2, b2, 1e-9 * size);
  }
};
}

//------------------------------------------------------------------------------
void vtkTetMeshDefectSearch::FindDuplicatesAndCracks(vtkTetMeshBuildState& state)
{
  vtkTetMeshValidationReport* report = state.GetReport();
  const vtkIdType numPoints = state.Mesh->GetNumberOfPoints();
  report->SetNumberOfDuplicatePoints(0);
  report->SetNumberOfCrackFaces(0);
  if (numPoints < 2)
  {
    return;
  }
  // Points bucketed by a hash of their coordinates with a counting sort (a few points per
  // bucket): equal coordinates share a bucket, where they are compared exactly.
  size_t numBuckets = 1;
  while (numBuckets < static_cast<size_t>(numPoints) / 2)
  {
    numBuckets <<= 1;
  }
  BucketPoints(state, numBuckets);
  const vtkIdType duplicates = GroupDuplicatePoints(state, numBuckets);
  report->SetNumberOfDuplicatePoints(duplicates);
  if (duplicates > 0)
  {
    report->SetNumberOfCrackFaces(CountCrackFaces(state));
  }
}

//------------------------------------------------------------------------------
// state.PointOrder: the point ids ordered by bucket (ascending inside each), bucket b from
// state.PointBucketStarts[b].
void vtkTetMeshDefectSearch::BucketPoints(vtkTetMeshBuildState& state, size_t numBuckets)
{
  const vtkIdType numPoints = state.Mesh->GetNumberOfPoints();
  const double* p = state.Mesh->Points.data();
  std::vector<uint32_t>& bucketOf = state.PointBuckets;
  bucketOf.resize(static_cast<size_t>(numPoints));
  vtkSMPTools::For(0, numPoints, 16384,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        uint64_t h = 0x9e3779b97f4a7c15ull;
        for (int c = 0; c < 3; ++c)
        {
          // + 0.0 turns -0.0 into 0.0, which compares equal to it.
          const double x = p[3 * i + c] + 0.0;
          uint64_t bits;
          std::memcpy(&bits, &x, sizeof(bits));
          h = (h ^ bits) * 0xff51afd7ed558ccdull;
          h ^= h >> 29;
        }
        bucketOf[i] = static_cast<uint32_t>((h >> 20) & (numBuckets - 1));
      }
    });
  std::vector<uint32_t>& bucketStart = state.PointBucketStarts;
  bucketStart.assign(numBuckets + 1, 0u);
  for (uint32_t b : bucketOf)
  {
    ++bucketStart[b + 1];
  }
  std::partial_sum(bucketStart.begin(), bucketStart.end(), bucketStart.begin());
  std::vector<uint32_t>& order = state.PointOrder;
  order.resize(static_cast<size_t>(numPoints));
  for (size_t i = 0; i < order.size(); ++i)
  {
    // bucketStart[b] runs ahead while filling bucket b - 1: shift back afterwards.
    order[bucketStart[bucketOf[i]]++] = static_cast<uint32_t>(i);
  }
  std::copy_backward(bucketStart.begin(), bucketStart.end() - 1, bucketStart.end());
  bucketStart[0] = 0;
}

//------------------------------------------------------------------------------
// state.Canonical[v]: the smallest id with v's coordinates (only where v has duplicates; left
// empty where no point has). Returns the number of duplicate points.
vtkIdType vtkTetMeshDefectSearch::GroupDuplicatePoints(
  vtkTetMeshBuildState& state, size_t numBuckets)
{
  const vtkIdType numPoints = state.Mesh->GetNumberOfPoints();
  const double* p = state.Mesh->Points.data();
  const std::vector<uint32_t>& bucketStart = state.PointBucketStarts;
  const std::vector<uint32_t>& order = state.PointOrder;
  std::vector<uint32_t>& canonical = state.Canonical;
  canonical.clear();
  vtkIdType duplicates = 0;
  for (size_t b = 0; b < numBuckets; ++b)
  {
    // Ids ascend inside a bucket: the first of a group is its smallest.
    for (uint32_t k = bucketStart[b]; k + 1 < bucketStart[b + 1]; ++k)
    {
      const uint32_t idK = order[k];
      if (!canonical.empty() && canonical[idK] != NoNeighbor)
      {
        continue; // already grouped with an earlier point
      }
      const double* pk = p + 3 * static_cast<size_t>(idK);
      for (uint32_t m = k + 1; m < bucketStart[b + 1]; ++m)
      {
        const uint32_t idM = order[m];
        const double* pm = p + 3 * static_cast<size_t>(idM);
        if ((canonical.empty() || canonical[idM] == NoNeighbor) && pk[0] == pm[0] &&
          pk[1] == pm[1] && pk[2] == pm[2])
        {
          if (canonical.empty())
          {
            canonical.assign(static_cast<size_t>(numPoints), NoNeighbor);
          }
          canonical[idK] = idK;
          canonical[idM] = idK;
          ++duplicates;
        }
      }
    }
  }
  return duplicates;
}

//------------------------------------------------------------------------------
// Boundary faces that overlap another boundary face reaching the same location through a
// different (duplicate) point id.
vtkIdType vtkTetMeshDefectSearch::CountCrackFaces(vtkTetMeshBuildState& state)
{
  vtkTetMesh* mesh = state.Mesh;
  const std::vector<uint32_t>& canonical = state.Canonical;
  const std::vector<uint32_t>& boundary = mesh->BoundaryFaces;
  BoundaryFaceGeometry geometry;
  geometry.Points = mesh->Points.data();
  geometry.TetPoints = mesh->TetPoints.data();
  // Boundary faces touching a duplicated point, listed under that point's canonical id.
  using Link = std::pair<uint32_t, uint32_t>; // (canonical id, index into boundary)
  std::vector<Link> links;
  for (size_t b = 0; b < boundary.size(); ++b)
  {
    for (int k = 0; k < 3; ++k)
    {
      const uint32_t v = geometry.FacePoint(boundary[b], k);
      if (canonical[v] != NoNeighbor)
      {
        links.emplace_back(canonical[v], static_cast<uint32_t>(b));
      }
    }
  }
  if (links.empty())
  {
    return 0;
  }
  std::sort(links.begin(), links.end());
  links.erase(std::unique(links.begin(), links.end()), links.end());

  // Each boundary face is tested on its own: in parallel.
  std::atomic<vtkIdType> cracks(0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(boundary.size()), 1024,
    [&](vtkIdType begin, vtkIdType end)
    {
      vtkIdType found = 0;
      std::vector<uint32_t> candidates;
      for (vtkIdType b = begin; b < end; ++b)
      {
        const uint32_t f = boundary[b];
        candidates.clear();
        for (int k = 0; k < 3; ++k)
        {
          const uint32_t v = geometry.FacePoint(f, k);
          if (canonical[v] == NoNeighbor)
          {
            continue;
          }
          auto range =
            std::equal_range(links.begin(), links.end(), std::make_pair(canonical[v], uint32_t(0)),
              [](const Link& x, const Link& y) { return x.first < y.first; });
          for (auto it = range.first; it != range.second; ++it)
          {
            const uint32_t g = boundary[it->second];
            // Only faces that reach this location through another point id: coincident but
            // not shared.
            bool usesV = false;
            for (int m = 0; m < 3; ++m)
            {
              usesV = usesV || geometry.FacePoint(g, m) == v;
            }
            if (g != f && !usesV)
            {
              candidates.push_back(g);
            }
          }
        }
        std::sort(candidates.begin(), candidates.end());
        candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
        for (uint32_t g : candidates)
        {
          if (geometry.Overlap(f, g))
          {
            ++found;
            break;
          }
        }
      }
      cracks += found;
    });
  return cracks;
}
