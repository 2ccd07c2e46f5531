/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetReferenceRayCaster.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetReferenceRayCaster.h"

#include "vtkTetExactArithmetic.h"
#include "vtkTetReferenceBVH.h"
#include "vtkTetReferenceMesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace
{
// Faces of a positively oriented tetrahedron, face i opposite point i, counter-clockwise seen
// from outside (docs/design.md).
const int FacePoints[4][3] = { { 1, 2, 3 }, { 0, 3, 2 }, { 0, 1, 3 }, { 0, 2, 1 } };
// Index of edge (i, j), i < j, in the table of six edge signs.
const int EdgeIndex[4][4] = { { -1, 0, 1, 2 }, { 0, -1, 3, 4 }, { 1, 3, -1, 5 }, { 2, 4, 5, -1 } };

//------------------------------------------------------------------------------
// Where the ray crosses the face (a, b, c) (transformed vertices, given in increasing order of
// point id so that both tetrahedra of a face compute the same numbers): z and the interpolated
// scalar, from the barycentric coordinates of the origin in the projected triangle. When the
// face is nearly parallel to the ray (projected area small against the magnitude of the terms)
// the weights are computed exactly and only the final division is rounded.
void FaceCrossing(const double* a, const double* b, const double* c, double sa, double sb,
  double sc, double& z, double& s)
{
  const double eBC = b[0] * c[1] - b[1] * c[0];
  const double eCA = c[0] * a[1] - c[1] * a[0];
  const double eAB = a[0] * b[1] - a[1] * b[0];
  const double magnitude = std::fabs(b[0] * c[1]) + std::fabs(b[1] * c[0]) +
    std::fabs(c[0] * a[1]) + std::fabs(c[1] * a[0]) + std::fabs(a[0] * b[1]) +
    std::fabs(a[1] * b[0]);
  const double d = eBC + eCA + eAB;
  if (std::fabs(d) > magnitude * (1.0 / 64.0))
  {
    // Relative error of the weights below 2^-44.
    z = (eBC * a[2] + eCA * b[2] + eAB * c[2]) / d;
    s = (eBC * sa + eCA * sb + eAB * sc) / d;
    return;
  }
  using namespace vtkTetExact;
  double wBC[4], wCA[4], wAB[4];
  const int nBC = Det2(b[0], b[1], c[0], c[1], wBC);
  const int nCA = Det2(c[0], c[1], a[0], a[1], wCA);
  const int nAB = Det2(a[0], a[1], b[0], b[1], wAB);
  double t1[16], scratch[32], den[16];
  const int n = ExpansionSum(nBC, wBC, nCA, wCA, t1, scratch);
  const int nden = ExpansionSum(n, t1, nAB, wAB, den, scratch);
  const double denominator = ExpansionEstimate(nden, den);
  auto weighted = [&](double va, double vb, double vc)
  {
    double pa[8], pb[8], pc[8], sum1[16], sum2[24], tmp[32];
    const int na = ScaleExpansion(nBC, wBC, va, pa, tmp);
    const int nb = ScaleExpansion(nCA, wCA, vb, pb, tmp);
    const int nc = ScaleExpansion(nAB, wAB, vc, pc, tmp);
    const int n1 = ExpansionSum(na, pa, nb, pb, sum1, tmp);
    const int n2 = ExpansionSum(n1, sum1, nc, pc, sum2, tmp);
    return ExpansionEstimate(n2, sum2);
  };
  z = weighted(a[2], b[2], c[2]) / denominator;
  s = weighted(sa, sb, sc) / denominator;
}
}

//------------------------------------------------------------------------------
// The ray frame: a translation to a point O of the ray and a shear that maps the ray direction
// d onto the z axis, scaled so that z is the ray parameter (distance from O in units of |d|).
// (kx, ky, kz) is a cyclic permutation of the axes, swapped when d[kz] < 0, so that the frame
// keeps the orientation of space. Each vertex is transformed by the same code with the same
// inputs for every tetrahedron that uses it, so all of them see bitwise the same vertex.
class vtkTetReferenceRayCaster::vtkRayFrame
{
public:
  double O[3];
  int Kx, Ky, Kz;
  double Sx, Sy, Sz;

  void Set(const double origin[3], const double d[3])
  {
    this->Kz = 0;
    for (int k = 1; k < 3; ++k)
    {
      if (std::fabs(d[k]) > std::fabs(d[this->Kz]))
      {
        this->Kz = k;
      }
    }
    this->Kx = (this->Kz + 1) % 3;
    this->Ky = (this->Kx + 1) % 3;
    if (d[this->Kz] < 0.0)
    {
      std::swap(this->Kx, this->Ky);
    }
    this->Sx = d[this->Kx] / d[this->Kz];
    this->Sy = d[this->Ky] / d[this->Kz];
    this->Sz = 1.0 / d[this->Kz];
    for (int k = 0; k < 3; ++k)
    {
      this->O[k] = origin[k];
    }
  }

  void Transform(const double* p, double v[3]) const
  {
    const double a[3] = { p[0] - this->O[0], p[1] - this->O[1], p[2] - this->O[2] };
    v[0] = a[this->Kx] - this->Sx * a[this->Kz];
    v[1] = a[this->Ky] - this->Sy * a[this->Kz];
    v[2] = this->Sz * a[this->Kz];
  }
};

//------------------------------------------------------------------------------
void vtkTetReferenceRayCaster::CastRay(const vtkTetReferenceMesh& mesh, const double origin[3],
  const double d[3], double zmin, double zmax, std::vector<Hit>& hits)
{
  hits.clear();
  vtkRayFrame frame;
  frame.Set(origin, d);

  // Slab test in double against the (padded) boxes; a zero direction component becomes a tiny
  // one, which keeps the products finite and the test conservative.
  double inv[3];
  for (int k = 0; k < 3; ++k)
  {
    const double dk = d[k] != 0.0 ? d[k] : 1e-300;
    inv[k] = 1.0 / dk;
  }
  int stack[vtkTetReferenceBVH::TraversalStackSize];
  int top = 0;
  stack[top++] = 0;
  const vtkTetReferenceBVH::Node* nodes = mesh.Nodes.data();
  while (top > 0)
  {
    const vtkTetReferenceBVH::Node& node = nodes[stack[--top]];
    double tnear = zmin, tfar = zmax;
    for (int k = 0; k < 3; ++k)
    {
      const double t0 = (node.Min[k] - origin[k]) * inv[k];
      const double t1 = (node.Max[k] - origin[k]) * inv[k];
      tnear = std::max(tnear, std::min(t0, t1));
      tfar = std::min(tfar, std::max(t0, t1));
    }
    if (!(tnear <= tfar))
    {
      continue;
    }
    if (node.Count == 0)
    {
      stack[top++] = node.Start;
      stack[top++] = node.Start + 1;
      continue;
    }
    for (int32_t t = node.Start; t < node.Start + node.Count; ++t)
    {
      Hit hit;
      if (CrossTetrahedron(mesh, frame, t, zmin, zmax, hit))
      {
        hits.push_back(hit);
      }
    }
  }
  std::sort(hits.begin(), hits.end());
}

//------------------------------------------------------------------------------
// Whether the ray crosses tetrahedron `tet` within (zmin, zmax), and where (`hit`).
bool vtkTetReferenceRayCaster::CrossTetrahedron(const vtkTetReferenceMesh& mesh,
  const vtkRayFrame& frame, vtkIdType t, double zmin, double zmax, Hit& hit)
{
  const vtkIdType* ids = mesh.Tets.data() + 4 * static_cast<size_t>(t);
  double v[4][3];
  for (int k = 0; k < 4; ++k)
  {
    frame.Transform(mesh.Points.data() + 3 * ids[k], v[k]);
  }
  // Quick rejections, strict so that the tie-breaking below keeps the final word.
  if ((v[0][0] > 0 && v[1][0] > 0 && v[2][0] > 0 && v[3][0] > 0) ||
    (v[0][0] < 0 && v[1][0] < 0 && v[2][0] < 0 && v[3][0] < 0) ||
    (v[0][1] > 0 && v[1][1] > 0 && v[2][1] > 0 && v[3][1] > 0) ||
    (v[0][1] < 0 && v[1][1] < 0 && v[2][1] < 0 && v[3][1] < 0))
  {
    return false;
  }
  const double zlo = std::min(std::min(v[0][2], v[1][2]), std::min(v[2][2], v[3][2]));
  const double zhi = std::max(std::max(v[0][2], v[1][2]), std::max(v[2][2], v[3][2]));
  if (zhi <= zmin || zlo >= zmax)
  {
    return false;
  }
  // Exact side of the ray for each edge; faces whose three edges agree are crossed.
  int sign[6];
  for (int i = 0; i < 4; ++i)
  {
    for (int j = i + 1; j < 4; ++j)
    {
      sign[EdgeIndex[i][j]] = vtkTetExact::OriginOrientation(v[i][0], v[i][1], v[j][0], v[j][1]);
    }
  }
  int entry = -1, exit = -1;
  for (int f = 0; f < 4; ++f)
  {
    int s[3];
    for (int e = 0; e < 3; ++e)
    {
      const int a = FacePoints[f][e], b = FacePoints[f][(e + 1) % 3];
      s[e] = a < b ? sign[EdgeIndex[a][b]] : -sign[EdgeIndex[b][a]];
    }
    if (s[0] == s[1] && s[1] == s[2] && s[0] != 0)
    {
      if (s[0] > 0)
      {
        exit = f;
      }
      else
      {
        entry = f;
      }
    }
  }
  if (entry < 0 || exit < 0)
  {
    return false;
  }
  double z[2], s[2];
  const int faces[2] = { entry, exit };
  for (int q = 0; q < 2; ++q)
  {
    int local[3] = { FacePoints[faces[q]][0], FacePoints[faces[q]][1], FacePoints[faces[q]][2] };
    std::sort(local, local + 3, [ids](int a, int b) { return ids[a] < ids[b]; });
    double sv[3] = { 0.0, 0.0, 0.0 };
    if (!mesh.CellScalars)
    {
      for (int k = 0; k < 3; ++k)
      {
        sv[k] = mesh.Scalars[ids[local[k]]];
      }
    }
    FaceCrossing(v[local[0]], v[local[1]], v[local[2]], sv[0], sv[1], sv[2], z[q], s[q]);
  }
  if (mesh.CellScalars)
  {
    s[0] = s[1] = mesh.Scalars[t];
  }
  // Clip to the near plane and the far plane or opaque depth.
  const double z0 = std::max(z[0], zmin), z1 = std::min(z[1], zmax);
  if (!(z1 > z0))
  {
    return false;
  }
  hit.Z0 = z0;
  hit.Z1 = z1;
  hit.S0 = s[0];
  hit.S1 = s[1];
  if (z0 != z[0] || z1 != z[1])
  {
    const double span = z[1] - z[0];
    hit.S0 = s[0] + (s[1] - s[0]) * ((z0 - z[0]) / span);
    hit.S1 = s[0] + (s[1] - s[0]) * ((z1 - z[0]) / span);
  }
  hit.Tet = t;
  return true;
}
