/*=========================================================================

  Program:   TiledRayCast
  Module:    TetMeshTestUtilities.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Checks shared by the vtkTetMesh tests: invariants that every built mesh must satisfy,
// written independently of the builder (plain loops, VTK's surface filter as the reference for
// boundary faces). Each check returns an empty string or a description of the first failure.
#ifndef TetMeshTestUtilities_h
#define TetMeshTestUtilities_h

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkDataSet.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkTetMesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#define TRC_CHECK(cond)                                                                            \
  do                                                                                               \
  {                                                                                                \
    if (!(cond))                                                                                   \
    {                                                                                              \
      std::cerr << __FILE__ << ":" << __LINE__ << ": check failed: " #cond << std::endl;           \
      return EXIT_FAILURE;                                                                         \
    }                                                                                              \
  } while (false)

// Runs a check that returns an error string.
#define TRC_CHECK_EMPTY(expr)                                                                      \
  do                                                                                               \
  {                                                                                                \
    const std::string trcMessage = (expr);                                                         \
    if (!trcMessage.empty())                                                                       \
    {                                                                                              \
      std::cerr << __FILE__ << ":" << __LINE__ << ": " #expr ": " << trcMessage << std::endl;      \
      return EXIT_FAILURE;                                                                         \
    }                                                                                              \
  } while (false)

namespace trc
{
using Triangle = std::array<vtkIdType, 3>;

inline Triangle SortedFace(vtkTetMesh* mesh, vtkIdType t, int face)
{
  const uint32_t* tp = mesh->GetTetPoints() + 4 * t;
  Triangle f = { static_cast<vtkIdType>(tp[vtkTetMesh::FacePoints[face][0]]),
    static_cast<vtkIdType>(tp[vtkTetMesh::FacePoints[face][1]]),
    static_cast<vtkIdType>(tp[vtkTetMesh::FacePoints[face][2]]) };
  std::sort(f.begin(), f.end());
  return f;
}

// t's neighbour across i is n through j <=> n's neighbour across j is t through i, and the two
// faces have the same three points. Also: the boundary list holds exactly the faces without a
// neighbour, in increasing order.
inline std::string CheckNeighbors(vtkTetMesh* mesh)
{
  std::ostringstream error;
  const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
  const uint32_t* nb = mesh->GetTetNeighbors();
  std::vector<uint32_t> boundary;
  for (vtkIdType t = 0; t < numTets; ++t)
  {
    for (int i = 0; i < 4; ++i)
    {
      const uint32_t word = nb[4 * t + i];
      const uint32_t self = static_cast<uint32_t>((t << 2) | i);
      if (word == vtkTetMesh::NoNeighbor)
      {
        boundary.push_back(self);
        continue;
      }
      const vtkIdType n = word >> 2;
      const int j = static_cast<int>(word & 3u);
      if (n >= numTets)
      {
        error << "tet " << t << " face " << i << ": neighbour " << n << " out of range";
        return error.str();
      }
      if (n == t)
      {
        error << "tet " << t << " face " << i << " is its own neighbour";
        return error.str();
      }
      if (nb[4 * n + j] != self)
      {
        error << "tet " << t << " face " << i << " -> tet " << n << " face " << j
              << ", which points back to word " << nb[4 * n + j];
        return error.str();
      }
      if (SortedFace(mesh, t, i) != SortedFace(mesh, n, j))
      {
        error << "tet " << t << " face " << i << " and tet " << n << " face " << j
              << " do not have the same points";
        return error.str();
      }
    }
  }
  const vtkIdType numFaces = mesh->GetNumberOfBoundaryFaces();
  if (static_cast<vtkIdType>(boundary.size()) != numFaces ||
    !std::equal(boundary.begin(), boundary.end(), mesh->GetBoundaryFaces()))
  {
    error << "the boundary list (" << numFaces << " faces) is not the " << boundary.size()
          << " faces without neighbour";
    return error.str();
  }
  return std::string();
}

// Positive orientation and outward normals: for every non-degenerate tetrahedron det > 0 and
// the opposite point lies strictly behind each face's unit normal; degenerate ones must not be
// inverted beyond rounding (1e-9 of the bounding box diagonal).
inline std::string CheckOrientation(vtkTetMesh* mesh)
{
  std::ostringstream error;
  double bounds[6];
  mesh->GetBounds(bounds);
  const double slack = 1e-9 *
    std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
      (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
      (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
  const uint32_t* tp = mesh->GetTetPoints();
  const double* p = mesh->GetPoints();
  for (vtkIdType t = 0; t < numTets; ++t)
  {
    const bool degenerate = (mesh->GetTetFlags()[t] & vtkTetMesh::Degenerate) != 0;
    const double volume = mesh->ComputeSignedVolume(t);
    if (!degenerate && !(volume > 0.0))
    {
      error << "tet " << t << " has volume " << volume;
      return error.str();
    }
    double n[12];
    mesh->ComputeFaceNormals(t, n, true);
    for (int i = 0; i < 4; ++i)
    {
      const double* opposite = p + 3 * tp[4 * t + i];
      const double* a = p + 3 * tp[4 * t + vtkTetMesh::FacePoints[i][0]];
      const double d = (opposite[0] - a[0]) * n[3 * i] + (opposite[1] - a[1]) * n[3 * i + 1] +
        (opposite[2] - a[2]) * n[3 * i + 2];
      if (degenerate ? d > slack : !(d < 0.0))
      {
        error << "tet " << t << " face " << i << ": the opposite point is " << d
              << " in front of the outward normal";
        return error.str();
      }
    }
  }
  return std::string();
}

// Largest |g . (x_k - shift) + c - s_k| over the vertices of non-degenerate tetrahedra with
// finite scalars, relative to max(|min|, |max|, max - min) of the scalars.
inline double ScalarReproductionError(vtkTetMesh* mesh)
{
  const double* s = mesh->GetPointScalars();
  if (!s)
  {
    return 0.0;
  }
  double range[2], shift[3];
  mesh->GetScalarRange(range);
  mesh->GetShift(shift);
  const double scale =
    std::max({ std::abs(range[0]), std::abs(range[1]), range[1] - range[0], 1e-300 });
  const uint32_t* tp = mesh->GetTetPoints();
  const double* p = mesh->GetPoints();
  double worst = 0.0;
  for (vtkIdType t = 0; t < mesh->GetNumberOfTetrahedra(); ++t)
  {
    double gc[4];
    if ((mesh->GetTetFlags()[t] & vtkTetMesh::Degenerate) || !mesh->ComputeScalarGradient(t, gc))
    {
      continue;
    }
    for (int k = 0; k < 4; ++k)
    {
      const double* x = p + 3 * tp[4 * t + k];
      const double value =
        gc[0] * (x[0] - shift[0]) + gc[1] * (x[1] - shift[1]) + gc[2] * (x[2] - shift[2]) + gc[3];
      worst = std::max(worst, std::abs(value - s[tp[4 * t + k]]) / scale);
    }
  }
  return worst;
}

// The boundary faces of the mesh as sorted point-id triples, sorted.
inline std::vector<Triangle> MeshBoundary(vtkTetMesh* mesh)
{
  std::vector<Triangle> faces;
  const uint32_t* boundary = mesh->GetBoundaryFaces();
  for (vtkIdType b = 0; b < mesh->GetNumberOfBoundaryFaces(); ++b)
  {
    faces.push_back(SortedFace(mesh, boundary[b] >> 2, static_cast<int>(boundary[b] & 3u)));
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

// VTK's own surface of a data set, as input point ids. Triangles are returned as sorted
// triples; `quads` counts the other polygons (and `others` their triangles).
inline std::vector<Triangle> SurfaceFilterBoundary(vtkDataSet* input, vtkIdType* quads = nullptr)
{
  vtkNew<vtkDataSetSurfaceFilter> surface;
  surface->SetInputData(input);
  surface->PassThroughPointIdsOn();
  surface->Update();
  vtkPolyData* poly = surface->GetOutput();
  auto* ids = vtkIdTypeArray::SafeDownCast(poly->GetPointData()->GetArray("vtkOriginalPointIds"));
  std::vector<Triangle> faces;
  vtkIdType numQuads = 0;
  vtkIdType npts;
  const vtkIdType* pts;
  vtkCellArray* polys = poly->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(npts, pts);)
  {
    if (npts == 3 && ids)
    {
      Triangle f = { ids->GetValue(pts[0]), ids->GetValue(pts[1]), ids->GetValue(pts[2]) };
      std::sort(f.begin(), f.end());
      faces.push_back(f);
    }
    else
    {
      ++numQuads;
    }
  }
  if (quads)
  {
    *quads = numQuads;
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}
}

#endif
// VTK-HeaderTest-Exclude: TetMeshTestUtilities.h
