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

#include "TiledRayCastTestCheck.h" // For TRC_CHECK

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkDataSet.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkTetMesh.h"
#include "vtkTetMeshCompactLayout.h"
#include "vtkTetMeshPaperLayout.h"
#include "vtkTypeUInt32Array.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

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
// neighbour (of tetrahedra not left out), in increasing order.
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
        // A tetrahedron left out (overlapping) has no boundary face either.
        if (!(mesh->GetTetFlags()[t] & vtkTetMesh::Overlapping))
        {
          boundary.push_back(self);
        }
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
  // Neighbours see their shared face in opposite orders (the same outward side from both),
  // degenerate tetrahedra included: their volume cannot orient them, their neighbours do.
  const uint32_t* neighbors = mesh->GetTetNeighbors();
  auto order = [&](uint32_t face)
  {
    const uint32_t* ids = tp + 4 * static_cast<size_t>(face >> 2);
    const int* fp = vtkTetMesh::FacePoints[face & 3u];
    std::array<uint32_t, 3> v = { ids[fp[0]], ids[fp[1]], ids[fp[2]] };
    std::rotate(v.begin(), std::min_element(v.begin(), v.end()), v.end());
    return v;
  };
  for (uint32_t face = 0; face < 4 * static_cast<uint32_t>(numTets); ++face)
  {
    const uint32_t other = neighbors[face];
    if (other == vtkTetMesh::NoNeighbor)
    {
      continue;
    }
    const std::array<uint32_t, 3> a = order(face), b = order(other);
    if (a[0] != b[0] || a[1] != b[2] || a[2] != b[1])
    {
      error << "tet " << (face >> 2) << " face " << (face & 3u) << " and its neighbour tet "
            << (other >> 2) << " face " << (other & 3u) << " see it with the same orientation";
      return error.str();
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

// The paper layout decodes to the mesh: vertices (shifted, in float), unit outward normals (to
// 1e-6), neighbours as texel coordinates of the right tetrahedra, and (g, c). Returns in
// `scalarError` the worst |g . v + c - s| at the vertices, evaluated in float from the texels
// as a shader would, relative to the scalar scale (non-degenerate tetrahedra).
inline std::string CheckPaperLayout(
  vtkTetMesh* mesh, vtkTetMeshPaperLayout* layout, double* scalarError = nullptr)
{
  std::ostringstream error;
  const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
  auto* vertices = vtkFloatArray::SafeDownCast(layout->GetArray(0));
  auto* normals = vtkFloatArray::SafeDownCast(layout->GetArray(1));
  auto* nbs = vtkFloatArray::SafeDownCast(layout->GetArray(2));
  if (!vertices || !normals || !nbs || layout->GetNumberOfArrays() != 3)
  {
    return "missing arrays";
  }
  int size[2];
  layout->GetArrayTextureSize(0, size);
  const vtkIdType w = size[0];
  if (w != layout->GetTextureWidth() || size[1] != 3 * ((numTets + w - 1) / w))
  {
    error << "texture size " << size[0] << " x " << size[1];
    return error.str();
  }
  double shift[3], range[2];
  mesh->GetShift(shift);
  mesh->GetScalarRange(range);
  const double scale =
    std::max({ std::abs(range[0]), std::abs(range[1]), range[1] - range[0], 1e-300 });
  const double* p = mesh->GetPoints();
  const uint32_t* tp = mesh->GetTetPoints();
  const uint32_t* nb = mesh->GetTetNeighbors();
  const double* s = mesh->GetPointScalars();
  double worst = 0.0;
  auto texel = [&](vtkFloatArray* a, vtkIdType t, int row)
  { return a->GetPointer(0) + 4 * ((3 * (t / w) + row) * w + t % w); };
  for (vtkIdType t = 0; t < numTets; ++t)
  {
    float v[4][3], n[4][3];
    for (int k = 0; k < 3; ++k)
    {
      const float* tv = texel(vertices, t, k);
      const float* tn = texel(normals, t, k);
      for (int c = 0; c < 3; ++c)
      {
        v[k][c] = tv[c];
        n[k][c] = tn[c];
      }
      v[3][k] = tv[3];
      n[3][k] = tn[3];
    }
    double normal[12];
    mesh->ComputeFaceNormals(t, normal, true);
    for (int k = 0; k < 4; ++k)
    {
      for (int c = 0; c < 3; ++c)
      {
        const float expected = static_cast<float>(p[3 * tp[4 * t + k] + c] - shift[c]);
        if (v[k][c] != expected)
        {
          error << "tet " << t << " vertex " << k << ": " << v[k][c] << " != " << expected;
          return error.str();
        }
        if (std::abs(n[k][c] - normal[3 * k + c]) > 1e-6)
        {
          error << "tet " << t << " normal " << k << ": " << n[k][c] << " != " << normal[3 * k + c];
          return error.str();
        }
      }
      const float* a = texel(nbs, t, k / 2) + 2 * (k % 2);
      const uint32_t word = nb[4 * t + k];
      const float u = word == vtkTetMesh::NoNeighbor ? -1.0f : static_cast<float>((word >> 2) % w);
      const float vv =
        word == vtkTetMesh::NoNeighbor ? -1.0f : static_cast<float>(3 * ((word >> 2) / w));
      if (a[0] != u || a[1] != vv)
      {
        error << "tet " << t << " neighbour " << k << ": (" << a[0] << ", " << a[1] << ") != (" << u
              << ", " << vv << ")";
        return error.str();
      }
    }
    const float* gc = texel(nbs, t, 2);
    double expected[4];
    const bool finite = mesh->ComputeScalarGradient(t, expected);
    expected[3] -= mesh->GetScalarShift(); // scalars are stored shifted
    for (int k = 0; k < 4; ++k)
    {
      const float e = finite ? static_cast<float>(expected[k])
                             : (k < 3 ? 0.0f : std::numeric_limits<float>::infinity());
      if (gc[k] != e)
      {
        error << "tet " << t << " scalar texel " << k << ": " << gc[k] << " != " << e;
        return error.str();
      }
    }
    if (s && finite && !(mesh->GetTetFlags()[t] & vtkTetMesh::Degenerate))
    {
      for (int k = 0; k < 4; ++k)
      {
        const float value = gc[0] * v[k][0] + gc[1] * v[k][1] + gc[2] * v[k][2] + gc[3];
        worst = std::max(
          worst, std::abs(value - (s[tp[4 * t + k]] - mesh->GetScalarShift())) / scale);
      }
    }
  }
  if (scalarError)
  {
    *scalarError = worst;
  }
  if (layout->GetNumberOfBytes() != 3 * 16 * w * size[1])
  {
    return "byte count";
  }
  return std::string();
}

// The compact layout holds the mesh's arrays: tetrahedron points and neighbours as they are,
// points shifted in float with their scalar, boundary faces as outward point ids plus word.
inline std::string CheckCompactLayout(vtkTetMesh* mesh, vtkTetMeshCompactLayout* layout)
{
  std::ostringstream error;
  const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
  const vtkIdType numPoints = mesh->GetNumberOfPoints();
  auto* tetPoints = vtkTypeUInt32Array::SafeDownCast(layout->GetArray(0));
  auto* neighbors = vtkTypeUInt32Array::SafeDownCast(layout->GetArray(1));
  auto* points = vtkFloatArray::SafeDownCast(layout->GetArray(2));
  auto* boundary = vtkTypeUInt32Array::SafeDownCast(layout->GetBoundaryArray());
  if (!tetPoints || !neighbors || !points || !boundary)
  {
    return "missing arrays";
  }
  if (tetPoints->GetNumberOfTuples() != numTets || neighbors->GetNumberOfTuples() != numTets ||
    points->GetNumberOfTuples() != numPoints ||
    boundary->GetNumberOfTuples() != mesh->GetNumberOfBoundaryFaces())
  {
    return "array sizes";
  }
  if (!std::equal(
        mesh->GetTetPoints(), mesh->GetTetPoints() + 4 * numTets, tetPoints->GetPointer(0)) ||
    !std::equal(
      mesh->GetTetNeighbors(), mesh->GetTetNeighbors() + 4 * numTets, neighbors->GetPointer(0)))
  {
    return "tetrahedron arrays differ from the mesh";
  }
  double shift[3];
  mesh->GetShift(shift);
  const double* p = mesh->GetPoints();
  const double* s = mesh->GetPointScalars();
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    const float* texel = points->GetPointer(4 * i);
    for (int c = 0; c < 3; ++c)
    {
      if (texel[c] != static_cast<float>(p[3 * i + c] - shift[c]))
      {
        error << "point " << i;
        return error.str();
      }
    }
    const float expected = !s ? 0.0f
      : std::isfinite(s[i])   ? static_cast<float>(s[i] - mesh->GetScalarShift())
                              : std::numeric_limits<float>::infinity();
    if (texel[3] != expected)
    {
      error << "point " << i << " scalar";
      return error.str();
    }
  }
  const uint32_t* faces = mesh->GetBoundaryFaces();
  const uint32_t* tp = mesh->GetTetPoints();
  for (vtkIdType f = 0; f < mesh->GetNumberOfBoundaryFaces(); ++f)
  {
    const uint32_t* texel = boundary->GetPointer(4 * f);
    const uint32_t* ids = tp + 4 * (faces[f] >> 2);
    const int* fp = vtkTetMesh::FacePoints[faces[f] & 3u];
    if (texel[0] != ids[fp[0]] || texel[1] != ids[fp[1]] || texel[2] != ids[fp[2]] ||
      texel[3] != faces[f])
    {
      error << "boundary face " << f;
      return error.str();
    }
  }
  const vtkIdType bytes =
    16 * (2 * numTets + numPoints) + (mesh->GetHasCellScalars() ? 4 * numTets : 0);
  if (layout->GetNumberOfBytes() != bytes ||
    layout->GetNumberOfBytesWithBoundary() != bytes + 16 * mesh->GetNumberOfBoundaryFaces())
  {
    return "byte count";
  }
  return std::string();
}
}

#endif
// VTK-HeaderTest-Exclude: TetMeshTestUtilities.h
