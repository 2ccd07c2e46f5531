/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetReferenceRenderer.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetReferenceRenderer.h"

#include "vtkAbstractMapper.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkGenericCell.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkScalarsToColors.h"
#include "vtkSmartPointer.h"
#include "vtkTetExactArithmetic.h"
#include "vtkTetReferenceOverlaps.h"
#include "vtkTetRayIntegrator.h"
#include "vtkTetScalarSelection.h"
#include "vtkTimerLog.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace
{
const char* const CarriedScalarsName = "vtkTetReferenceRenderer_Scalars";

// A ray stops once its transmittance is below this: what lies behind changes no value by more.
constexpr double TerminationDepth = 36.0; // exp(-36) = 2.3e-16

//------------------------------------------------------------------------------
// Bounding volume hierarchy over the tetrahedra (binned surface area heuristic). Boxes are
// stored in float, rounded outwards and padded, so that the hierarchy only ever yields a
// superset of the tetrahedra that a ray meets.
struct BVHNode
{
  float Min[3];
  float Max[3];
  int32_t Start; // leaf: first tetrahedron; inner node: index of the first of two children
  int32_t Count; // leaf: number of tetrahedra (> 0); inner node: 0
};

constexpr int LeafSize = 4;
constexpr int BinCount = 16;
constexpr int MaxBuildDepth = 100;
constexpr int TraversalStackSize = MaxBuildDepth + 64;

float RoundDown(double x)
{
  float f = static_cast<float>(x);
  if (static_cast<double>(f) > x)
  {
    f = std::nextafter(f, -std::numeric_limits<float>::infinity());
  }
  return f;
}

float RoundUp(double x)
{
  float f = static_cast<float>(x);
  if (static_cast<double>(f) < x)
  {
    f = std::nextafter(f, std::numeric_limits<float>::infinity());
  }
  return f;
}

double SurfaceArea(const double b[6])
{
  const double dx = b[3] - b[0], dy = b[4] - b[1], dz = b[5] - b[2];
  return dx * dy + dy * dz + dz * dx;
}

void EmptyBox(double b[6])
{
  b[0] = b[1] = b[2] = std::numeric_limits<double>::infinity();
  b[3] = b[4] = b[5] = -std::numeric_limits<double>::infinity();
}

void GrowBox(double b[6], const double* other)
{
  for (int i = 0; i < 3; ++i)
  {
    b[i] = std::min(b[i], other[i]);
    b[i + 3] = std::max(b[i + 3], other[i + 3]);
  }
}

// boxes: 6 per item (min xyz, max xyz). order gets the item permutation of the leaves.
void BuildBVH(const std::vector<double>& boxes, double pad, std::vector<int>& order,
  std::vector<BVHNode>& nodes)
{
  const int n = static_cast<int>(boxes.size() / 6);
  order.resize(n);
  std::vector<double> centroids(3 * static_cast<size_t>(n));
  for (int i = 0; i < n; ++i)
  {
    order[i] = i;
    for (int k = 0; k < 3; ++k)
    {
      centroids[3 * i + k] = 0.5 * (boxes[6 * i + k] + boxes[6 * i + 3 + k]);
    }
  }
  nodes.clear();
  nodes.reserve(2 * static_cast<size_t>(std::max(n / LeafSize, 1)) + 1);
  nodes.push_back(BVHNode());
  struct Task
  {
    int Node, Begin, End, Depth;
  };
  std::vector<Task> tasks;
  tasks.push_back({ 0, 0, n, 0 });
  while (!tasks.empty())
  {
    const Task t = tasks.back();
    tasks.pop_back();
    double box[6], cbox[6];
    EmptyBox(box);
    EmptyBox(cbox);
    for (int i = t.Begin; i < t.End; ++i)
    {
      GrowBox(box, &boxes[6 * static_cast<size_t>(order[i])]);
      const double* c = &centroids[3 * static_cast<size_t>(order[i])];
      const double cc[6] = { c[0], c[1], c[2], c[0], c[1], c[2] };
      GrowBox(cbox, cc);
    }
    BVHNode& node = nodes[t.Node];
    for (int k = 0; k < 3; ++k)
    {
      node.Min[k] = RoundDown(box[k] - pad);
      node.Max[k] = RoundUp(box[k + 3] + pad);
    }
    const int count = t.End - t.Begin;
    if (count <= LeafSize)
    {
      node.Start = t.Begin;
      node.Count = count;
      continue;
    }
    int axis = 0;
    for (int k = 1; k < 3; ++k)
    {
      if (cbox[k + 3] - cbox[k] > cbox[axis + 3] - cbox[axis])
      {
        axis = k;
      }
    }
    const double cmin = cbox[axis], extent = cbox[axis + 3] - cbox[axis];
    int mid = -1;
    if (extent > 0.0 && t.Depth < MaxBuildDepth)
    {
      auto binOf = [&](int item)
      {
        const int b = static_cast<int>(
          BinCount * ((centroids[3 * static_cast<size_t>(item) + axis] - cmin) / extent));
        return std::min(BinCount - 1, std::max(0, b));
      };
      int binCount[BinCount] = {};
      double binBox[BinCount][6];
      for (int b = 0; b < BinCount; ++b)
      {
        EmptyBox(binBox[b]);
      }
      for (int i = t.Begin; i < t.End; ++i)
      {
        const int b = binOf(order[i]);
        ++binCount[b];
        GrowBox(binBox[b], &boxes[6 * static_cast<size_t>(order[i])]);
      }
      double rightArea[BinCount];
      int rightCount[BinCount];
      double acc[6];
      EmptyBox(acc);
      int accCount = 0;
      for (int b = BinCount - 1; b > 0; --b)
      {
        GrowBox(acc, binBox[b]);
        accCount += binCount[b];
        rightArea[b] = accCount ? SurfaceArea(acc) : 0.0;
        rightCount[b] = accCount;
      }
      EmptyBox(acc);
      accCount = 0;
      double bestCost = std::numeric_limits<double>::infinity();
      int bestSplit = -1;
      for (int b = 0; b < BinCount - 1; ++b)
      {
        GrowBox(acc, binBox[b]);
        accCount += binCount[b];
        if (accCount == 0 || rightCount[b + 1] == 0)
        {
          continue;
        }
        const double cost = SurfaceArea(acc) * accCount + rightArea[b + 1] * rightCount[b + 1];
        if (cost < bestCost)
        {
          bestCost = cost;
          bestSplit = b;
        }
      }
      if (bestSplit >= 0)
      {
        int* split = std::partition(
          &order[t.Begin], &order[0] + t.End, [&](int item) { return binOf(item) <= bestSplit; });
        mid = static_cast<int>(split - &order[0]);
      }
    }
    if (mid <= t.Begin || mid >= t.End)
    {
      // All centroids in one bin (or too deep): split at the median of the widest axis.
      mid = (t.Begin + t.End) / 2;
      std::nth_element(&order[t.Begin], &order[mid], &order[0] + t.End,
        [&](int a, int b)
        {
          return centroids[3 * static_cast<size_t>(a) + axis] <
            centroids[3 * static_cast<size_t>(b) + axis];
        });
    }
    const int first = static_cast<int>(nodes.size());
    node.Start = first;
    node.Count = 0;
    nodes.push_back(BVHNode());
    nodes.push_back(BVHNode());
    tasks.push_back({ first, t.Begin, mid, t.Depth + 1 });
    tasks.push_back({ first + 1, mid, t.End, t.Depth + 1 });
  }
}

//------------------------------------------------------------------------------
// The ray frame: a translation to a point O of the ray and a shear that maps the ray direction
// d onto the z axis, scaled so that z is the ray parameter (distance from O in units of |d|).
// (kx, ky, kz) is a cyclic permutation of the axes, swapped when d[kz] < 0, so that the frame
// keeps the orientation of space. Each vertex is transformed by the same code with the same
// inputs for every tetrahedron that uses it, so all of them see bitwise the same vertex.
struct RayFrame
{
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

struct Hit
{
  double Z0, Z1, S0, S1;
  vtkIdType Tet;
  bool operator<(const Hit& o) const
  {
    if (this->Z0 != o.Z0)
    {
      return this->Z0 < o.Z0;
    }
    if (this->Z1 != o.Z1)
    {
      return this->Z1 < o.Z1;
    }
    return this->Tet < o.Tet;
  }
};

// Faces of a positively oriented tetrahedron, face i opposite point i, counter-clockwise seen
// from outside (docs/design.md).
const int FacePoints[4][3] = { { 1, 2, 3 }, { 0, 3, 2 }, { 0, 1, 3 }, { 0, 2, 1 } };
// Index of edge (i, j), i < j, in the table of six edge signs.
const int EdgeIndex[4][4] = { { -1, 0, 1, 2 }, { 0, -1, 3, 4 }, { 1, 3, -1, 5 }, { 2, 4, 5, -1 } };
} // namespace

//------------------------------------------------------------------------------
class vtkTetReferenceRenderer::vtkInternals
{
public:
  // What the prepared mesh was built from.
  bool Valid = false;
  vtkDataSet* Input = nullptr;
  vtkMTimeType InputMTime = 0;
  int ScalarMode = -1, ArrayAccessMode = -1, ArrayId = -1;
  std::string ArrayName;
  // The one scalar taken from the array (vtkTetScalarSelection), resolved with the property.
  bool Magnitude = false;
  int Component = 0;
  double Matrix[16];

  // The prepared mesh, in world coordinates minus Center, tetrahedra in hierarchy order.
  std::vector<double> Points;
  std::vector<vtkIdType> Tets;
  std::vector<double> Scalars; // per point, or per tetrahedron with cell scalars
  bool CellScalars = false;
  std::vector<unsigned char> Transparent;
  std::vector<BVHNode> Nodes;
  double Center[3] = { 0.0, 0.0, 0.0 };
  size_t NumberOfOverlapping = 0; // tetrahedra left out (vtkTetReferenceOverlaps)

  // The property the integrator was initialised with.
  vtkVolumeProperty* Property = nullptr;
  vtkMTimeType PropertyMTime = 0;

  vtkSMPThreadLocal<std::vector<Hit>> Hits;

  bool Prepare(vtkTetReferenceRenderer* self, vtkDataSet* input, bool magnitude, int component,
    const double matrix[16], vtkIdType& degenerate, std::string& error);

  // Collect the tetrahedra the ray O + z d crosses for z in (zmin, zmax).
  void CastRay(const double origin[3], const double d[3], double zmin, double zmax,
    std::vector<Hit>& hits) const;
};

//------------------------------------------------------------------------------
bool vtkTetReferenceRenderer::vtkInternals::Prepare(vtkTetReferenceRenderer* self,
  vtkDataSet* input, bool magnitude, int component, const double matrix[16], vtkIdType& degenerate,
  std::string& error)
{
  this->Valid = false;
  degenerate = 0;

  // Scalars, reduced to one component.
  int cellFlag = -1;
  vtkDataArray* array = vtkAbstractMapper::GetScalars(
    input, self->ScalarMode, self->ArrayAccessMode, self->ArrayId, self->ArrayName, cellFlag);
  if (!array || array->GetNumberOfTuples() == 0)
  {
    error = "No scalars to render (check the scalar mode and the selected array).";
    return false;
  }
  if (cellFlag != 0 && cellFlag != 1)
  {
    error = "Field data scalars are not supported; use point or cell data.";
    return false;
  }
  const bool cellScalars = cellFlag == 1;
  const vtkIdType numTuples = array->GetNumberOfTuples();
  vtkNew<vtkDoubleArray> reduced;
  reduced->SetName(CarriedScalarsName);
  reduced->SetNumberOfTuples(numTuples);
  vtkTetScalarSelection::Extract(array, magnitude, component, reduced->GetPointer(0));
  this->Magnitude = magnitude;
  this->Component = component;

  // Tetrahedra: used as they are when the input is an unstructured grid whose 3D cells are all
  // tetrahedra (lower-dimensional cells are ignored); otherwise split by VTK.
  vtkUnstructuredGrid* grid = vtkUnstructuredGrid::SafeDownCast(input);
  bool direct = grid != nullptr;
  if (grid)
  {
    int dimension[256];
    std::fill(dimension, dimension + 256, -1);
    vtkNew<vtkGenericCell> cell;
    const vtkIdType numCells = grid->GetNumberOfCells();
    for (vtkIdType i = 0; i < numCells && direct; ++i)
    {
      const int type = grid->GetCellType(i);
      if (type == VTK_TETRA)
      {
        continue;
      }
      if (dimension[type] < 0)
      {
        cell->SetCellType(type);
        dimension[type] = cell->GetCellDimension();
      }
      direct = dimension[type] < 3;
    }
  }
  vtkDataSet* mesh = input;
  vtkDataArray* scalars = reduced;
  vtkSmartPointer<vtkUnstructuredGrid> triangulated;
  std::vector<vtkIdType> rawTets;
  std::vector<vtkIdType> tetCell; // the cell (of mesh) each tetrahedron comes from
  if (!direct)
  {
    // The reduced scalars ride along as an array of their own, so that point and cell
    // correspondences are the filter's business.
    vtkSmartPointer<vtkDataSet> copy = vtkSmartPointer<vtkDataSet>::Take(input->NewInstance());
    copy->ShallowCopy(input);
    if (cellScalars)
    {
      copy->GetCellData()->AddArray(reduced);
    }
    else
    {
      copy->GetPointData()->AddArray(reduced);
    }
    vtkNew<vtkDataSetTriangleFilter> split;
    split->SetInputData(copy);
    split->TetrahedraOnlyOn();
    split->Update();
    triangulated = split->GetOutput();
    mesh = triangulated;
    scalars = cellScalars ? triangulated->GetCellData()->GetArray(CarriedScalarsName)
                          : triangulated->GetPointData()->GetArray(CarriedScalarsName);
    if (!scalars)
    {
      error = "Splitting the cells into tetrahedra lost the scalars.";
      return false;
    }
  }
  vtkUnstructuredGrid* ug = vtkUnstructuredGrid::SafeDownCast(mesh);
  if (ug)
  {
    const vtkIdType numCells = ug->GetNumberOfCells();
    rawTets.reserve(4 * static_cast<size_t>(numCells));
    for (vtkIdType i = 0; i < numCells; ++i)
    {
      if (ug->GetCellType(i) != VTK_TETRA)
      {
        continue;
      }
      vtkIdType npts;
      const vtkIdType* pts;
      ug->GetCellPoints(i, npts, pts);
      rawTets.insert(rawTets.end(), pts, pts + 4);
      tetCell.push_back(i);
    }
  }
  const vtkIdType numPoints = mesh->GetNumberOfPoints();
  if (tetCell.empty() || numPoints < 4)
  {
    error = "The input has no tetrahedra (no 3D cells).";
    return false;
  }
  if (scalars->GetNumberOfTuples() != (cellScalars ? mesh->GetNumberOfCells() : numPoints))
  {
    error = "The scalars do not match the mesh.";
    return false;
  }

  // World coordinates, shifted to the centre of their bounds (precision far from the origin).
  std::vector<double> world(3 * static_cast<size_t>(numPoints));
  double bounds[6];
  EmptyBox(bounds);
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    double out[3];
    const double w = matrix[12] * p[0] + matrix[13] * p[1] + matrix[14] * p[2] + matrix[15];
    for (int r = 0; r < 3; ++r)
    {
      out[r] = (matrix[4 * r] * p[0] + matrix[4 * r + 1] * p[1] + matrix[4 * r + 2] * p[2] +
                 matrix[4 * r + 3]) /
        w;
      world[3 * i + r] = out[r];
    }
    if (std::isfinite(out[0]) && std::isfinite(out[1]) && std::isfinite(out[2]))
    {
      const double b[6] = { out[0], out[1], out[2], out[0], out[1], out[2] };
      GrowBox(bounds, b);
    }
  }
  if (!(bounds[0] <= bounds[3]))
  {
    error = "The mesh has no finite points.";
    return false;
  }
  for (int k = 0; k < 3; ++k)
  {
    this->Center[k] = 0.5 * (bounds[k] + bounds[k + 3]);
  }
  const double diagonal = std::sqrt((bounds[3] - bounds[0]) * (bounds[3] - bounds[0]) +
    (bounds[4] - bounds[1]) * (bounds[4] - bounds[1]) +
    (bounds[5] - bounds[2]) * (bounds[5] - bounds[2]));
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      world[3 * i + k] -= this->Center[k];
    }
  }

  // Positive orientation (docs/design.md); zero-volume tetrahedra hold nothing and are dropped.
  const size_t numRaw = tetCell.size();
  std::vector<vtkIdType> tets;
  std::vector<vtkIdType> keptCell;
  std::vector<double> boxes;
  tets.reserve(4 * numRaw);
  keptCell.reserve(numRaw);
  boxes.reserve(6 * numRaw);
  for (size_t t = 0; t < numRaw; ++t)
  {
    vtkIdType ids[4] = { rawTets[4 * t], rawTets[4 * t + 1], rawTets[4 * t + 2],
      rawTets[4 * t + 3] };
    const double* p[4];
    bool finite = true;
    for (int k = 0; k < 4; ++k)
    {
      if (ids[k] < 0 || ids[k] >= numPoints)
      {
        finite = false;
        break;
      }
      p[k] = &world[3 * ids[k]];
      finite = finite && std::isfinite(p[k][0]) && std::isfinite(p[k][1]) && std::isfinite(p[k][2]);
    }
    if (!finite)
    {
      ++degenerate;
      continue;
    }
    double u[3], v[3], w[3];
    for (int k = 0; k < 3; ++k)
    {
      u[k] = p[1][k] - p[0][k];
      v[k] = p[2][k] - p[0][k];
      w[k] = p[3][k] - p[0][k];
    }
    const double det = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
      u[2] * (v[0] * w[1] - v[1] * w[0]);
    if (!(det != 0.0) || !std::isfinite(det))
    {
      ++degenerate;
      continue;
    }
    if (det < 0.0)
    {
      std::swap(ids[2], ids[3]);
    }
    tets.insert(tets.end(), ids, ids + 4);
    keptCell.push_back(tetCell[t]);
    double box[6];
    EmptyBox(box);
    for (int k = 0; k < 4; ++k)
    {
      const double b[6] = { p[k][0], p[k][1], p[k][2], p[k][0], p[k][1], p[k][2] };
      GrowBox(box, b);
    }
    boxes.insert(boxes.end(), box, box + 6);
  }
  // Tetrahedra on the same side of a face they share overlap: all but the first of each side in
  // input order are left out, as the mesh builder does (vtkTetReferenceOverlaps).
  const std::vector<unsigned char> overlapping = vtkTetReferenceOverlaps::Find(tets);
  this->NumberOfOverlapping = 0;
  for (size_t t = 0, kept = 0; t < overlapping.size(); ++t)
  {
    if (overlapping[t])
    {
      ++this->NumberOfOverlapping;
      continue;
    }
    std::copy(tets.begin() + 4 * t, tets.begin() + 4 * t + 4, tets.begin() + 4 * kept);
    std::copy(boxes.begin() + 6 * t, boxes.begin() + 6 * t + 6, boxes.begin() + 6 * kept);
    keptCell[kept++] = keptCell[t];
  }
  keptCell.resize(keptCell.size() - this->NumberOfOverlapping);
  tets.resize(4 * keptCell.size());
  boxes.resize(6 * keptCell.size());
  const size_t numTets = keptCell.size();
  if (numTets == 0)
  {
    error = "All tetrahedra of the input are degenerate (zero volume).";
    return false;
  }
  if (numTets > static_cast<size_t>(std::numeric_limits<int32_t>::max() / 2))
  {
    error = "Too many tetrahedra for the reference renderer.";
    return false;
  }

  // The hierarchy; boxes padded far beyond any rounding of the ray frame.
  std::vector<int> order;
  BuildBVH(boxes, 1e-7 * diagonal + 1e-300, order, this->Nodes);

  // Store everything in hierarchy order.
  this->Points.swap(world);
  this->Tets.resize(4 * numTets);
  this->Transparent.resize(numTets);
  this->CellScalars = cellScalars;
  if (cellScalars)
  {
    this->Scalars.resize(numTets);
  }
  else
  {
    this->Scalars.resize(static_cast<size_t>(numPoints));
    for (vtkIdType i = 0; i < numPoints; ++i)
    {
      this->Scalars[i] = scalars->GetComponent(i, 0);
    }
  }
  for (size_t i = 0; i < numTets; ++i)
  {
    const int src = order[i];
    bool transparent = false;
    for (int k = 0; k < 4; ++k)
    {
      const vtkIdType id = tets[4 * static_cast<size_t>(src) + k];
      this->Tets[4 * i + k] = id;
      if (!cellScalars)
      {
        transparent = transparent || !std::isfinite(this->Scalars[id]);
      }
    }
    if (cellScalars)
    {
      const double value = scalars->GetComponent(keptCell[src], 0);
      this->Scalars[i] = value;
      transparent = !std::isfinite(value);
    }
    this->Transparent[i] = transparent ? 1 : 0;
  }

  this->Input = input;
  this->InputMTime = input->GetMTime();
  this->ScalarMode = self->ScalarMode;
  this->ArrayAccessMode = self->ArrayAccessMode;
  this->ArrayId = self->ArrayId;
  this->ArrayName = self->ArrayName ? self->ArrayName : "";
  std::copy(matrix, matrix + 16, this->Matrix);
  this->Valid = true;
  return true;
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::vtkInternals::CastRay(
  const double origin[3], const double d[3], double zmin, double zmax, std::vector<Hit>& hits) const
{
  hits.clear();
  RayFrame frame;
  frame.Set(origin, d);

  // Slab test in double against the (padded) boxes; a zero direction component becomes a tiny
  // one, which keeps the products finite and the test conservative.
  double inv[3];
  for (int k = 0; k < 3; ++k)
  {
    const double dk = d[k] != 0.0 ? d[k] : 1e-300;
    inv[k] = 1.0 / dk;
  }
  int stack[TraversalStackSize];
  int top = 0;
  stack[top++] = 0;
  const BVHNode* nodes = this->Nodes.data();
  const double* points = this->Points.data();
  const vtkIdType* tets = this->Tets.data();
  while (top > 0)
  {
    const BVHNode& node = nodes[stack[--top]];
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
      const vtkIdType* ids = tets + 4 * static_cast<size_t>(t);
      double v[4][3];
      for (int k = 0; k < 4; ++k)
      {
        frame.Transform(points + 3 * ids[k], v[k]);
      }
      // Quick rejections, strict so that the tie-breaking below keeps the final word.
      if ((v[0][0] > 0 && v[1][0] > 0 && v[2][0] > 0 && v[3][0] > 0) ||
        (v[0][0] < 0 && v[1][0] < 0 && v[2][0] < 0 && v[3][0] < 0) ||
        (v[0][1] > 0 && v[1][1] > 0 && v[2][1] > 0 && v[3][1] > 0) ||
        (v[0][1] < 0 && v[1][1] < 0 && v[2][1] < 0 && v[3][1] < 0))
      {
        continue;
      }
      const double zlo = std::min(std::min(v[0][2], v[1][2]), std::min(v[2][2], v[3][2]));
      const double zhi = std::max(std::max(v[0][2], v[1][2]), std::max(v[2][2], v[3][2]));
      if (zhi <= zmin || zlo >= zmax)
      {
        continue;
      }
      // Exact side of the ray for each edge; faces whose three edges agree are crossed.
      int sign[6];
      for (int i = 0; i < 4; ++i)
      {
        for (int j = i + 1; j < 4; ++j)
        {
          sign[EdgeIndex[i][j]] =
            vtkTetExact::OriginOrientation(v[i][0], v[i][1], v[j][0], v[j][1]);
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
        continue;
      }
      double z[2], s[2];
      const int faces[2] = { entry, exit };
      for (int q = 0; q < 2; ++q)
      {
        int local[3] = { FacePoints[faces[q]][0], FacePoints[faces[q]][1],
          FacePoints[faces[q]][2] };
        std::sort(local, local + 3, [ids](int a, int b) { return ids[a] < ids[b]; });
        double sv[3] = { 0.0, 0.0, 0.0 };
        if (!this->CellScalars)
        {
          for (int k = 0; k < 3; ++k)
          {
            sv[k] = this->Scalars[ids[local[k]]];
          }
        }
        FaceCrossing(v[local[0]], v[local[1]], v[local[2]], sv[0], sv[1], sv[2], z[q], s[q]);
      }
      if (this->CellScalars)
      {
        s[0] = s[1] = this->Scalars[t];
      }
      // Clip to the near plane and the far plane or opaque depth.
      const double z0 = std::max(z[0], zmin), z1 = std::min(z[1], zmax);
      if (!(z1 > z0))
      {
        continue;
      }
      Hit hit;
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
      hits.push_back(hit);
    }
  }
  std::sort(hits.begin(), hits.end());
}

//------------------------------------------------------------------------------
vtkStandardNewMacro(vtkTetReferenceRenderer);

//------------------------------------------------------------------------------
vtkTetReferenceRenderer::vtkTetReferenceRenderer()
  : Input(nullptr)
  , ScalarMode(VTK_SCALAR_MODE_DEFAULT)
  , ArrayAccessMode(VTK_GET_ARRAY_BY_ID)
  , ArrayId(-1)
  , ArrayName(nullptr)
  , VectorMode(vtkTetScalarSelection::DEFAULT)
  , VectorComponent(0)
  , VolumeProperty(nullptr)
  , Camera(nullptr)
  , VolumeMatrix(vtkMatrix4x4::New())
  , Volume(nullptr)
  , OpaqueDepth(nullptr)
  , DoublePrecisionOutput(0)
  , Output(vtkImageData::New())
  , Integrator(vtkTetRayIntegrator::New())
  , NumberOfTetrahedra(0)
  , NumberOfDegenerateTetrahedra(0)
  , LastPreparationTime(0.0)
  , LastRayCastTime(0.0)
  , Internals(new vtkInternals)
{
  this->ImageSize[0] = this->ImageSize[1] = 256;
  this->SampleOffset[0] = this->SampleOffset[1] = 0.5;
}

//------------------------------------------------------------------------------
vtkTetReferenceRenderer::~vtkTetReferenceRenderer()
{
  this->SetInputData(nullptr);
  this->SetVolumeProperty(nullptr);
  this->SetCamera(nullptr);
  this->SetVolume(nullptr);
  this->SetOpaqueDepth(nullptr);
  this->SetClippingPlanes(nullptr);
  this->SetArrayName(nullptr);
  this->VolumeMatrix->Delete();
  this->Output->Delete();
  this->Integrator->Delete();
  delete this->Internals;
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::SetInputData(vtkDataSet* input)
{
  vtkSetObjectBodyMacro(Input, vtkDataSet, input);
}

//------------------------------------------------------------------------------
vtkDataSet* vtkTetReferenceRenderer::GetInput()
{
  return this->Input;
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::SetVolumeProperty(vtkVolumeProperty* property)
{
  vtkSetObjectBodyMacro(VolumeProperty, vtkVolumeProperty, property);
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::SetCamera(vtkCamera* camera)
{
  vtkSetObjectBodyMacro(Camera, vtkCamera, camera);
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::SetVolume(vtkVolume* volume)
{
  vtkSetObjectBodyMacro(Volume, vtkVolume, volume);
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::SetClippingPlanes(vtkPlaneCollection* planes)
{
  vtkSetObjectBodyMacro(ClippingPlanes, vtkPlaneCollection, planes);
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::SetOpaqueDepth(vtkFloatArray* depth)
{
  vtkSetObjectBodyMacro(OpaqueDepth, vtkFloatArray, depth);
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::SetVolumeMatrix(vtkMatrix4x4* matrix)
{
  if (matrix)
  {
    this->VolumeMatrix->DeepCopy(matrix);
  }
  else
  {
    this->VolumeMatrix->Identity();
  }
  this->Modified();
}

//------------------------------------------------------------------------------
vtkMatrix4x4* vtkTetReferenceRenderer::GetVolumeMatrix()
{
  return this->VolumeMatrix;
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::SetScalarModeToDefault()
{
  this->SetScalarMode(VTK_SCALAR_MODE_DEFAULT);
}
void vtkTetReferenceRenderer::SetScalarModeToUsePointData()
{
  this->SetScalarMode(VTK_SCALAR_MODE_USE_POINT_DATA);
}
void vtkTetReferenceRenderer::SetScalarModeToUseCellData()
{
  this->SetScalarMode(VTK_SCALAR_MODE_USE_CELL_DATA);
}
void vtkTetReferenceRenderer::SetScalarModeToUsePointFieldData()
{
  this->SetScalarMode(VTK_SCALAR_MODE_USE_POINT_FIELD_DATA);
}
void vtkTetReferenceRenderer::SetScalarModeToUseCellFieldData()
{
  this->SetScalarMode(VTK_SCALAR_MODE_USE_CELL_FIELD_DATA);
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::SelectScalarArray(int arrayNum)
{
  if (this->ArrayId == arrayNum && this->ArrayAccessMode == VTK_GET_ARRAY_BY_ID)
  {
    return;
  }
  this->ArrayId = arrayNum;
  this->ArrayAccessMode = VTK_GET_ARRAY_BY_ID;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::SelectScalarArray(const char* arrayName)
{
  if (!arrayName)
  {
    return;
  }
  this->SetArrayName(arrayName);
  this->ArrayAccessMode = VTK_GET_ARRAY_BY_NAME;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::SetVectorModeToDefault()
{
  this->SetVectorMode(vtkTetScalarSelection::DEFAULT);
}
void vtkTetReferenceRenderer::SetVectorModeToComponent()
{
  this->SetVectorMode(vtkScalarsToColors::COMPONENT);
}
void vtkTetReferenceRenderer::SetVectorModeToMagnitude()
{
  this->SetVectorMode(vtkScalarsToColors::MAGNITUDE);
}

//------------------------------------------------------------------------------
vtkImageData* vtkTetReferenceRenderer::GetOutput()
{
  return this->Output;
}

//------------------------------------------------------------------------------
vtkTetRayIntegrator* vtkTetReferenceRenderer::GetIntegrator()
{
  return this->Integrator;
}

//------------------------------------------------------------------------------
int vtkTetReferenceRenderer::Render()
{
  this->Output->Initialize();
  this->LastPreparationTime = 0.0;
  this->LastRayCastTime = 0.0;
  vtkInternals& in = *this->Internals;

  if (!this->Input)
  {
    vtkErrorMacro("No input.");
    return 0;
  }
  if (this->Input->GetNumberOfPoints() == 0 || this->Input->GetNumberOfCells() == 0)
  {
    vtkErrorMacro("The input is empty.");
    return 0;
  }
  vtkVolumeProperty* property = this->VolumeProperty;
  if (!property && this->Volume)
  {
    property = this->Volume->GetProperty();
  }
  if (!property)
  {
    vtkErrorMacro("No volume property.");
    return 0;
  }
  if (!this->Camera)
  {
    vtkErrorMacro("No camera.");
    return 0;
  }
  const int width = this->ImageSize[0], height = this->ImageSize[1];
  if (width <= 0 || height <= 0 || static_cast<double>(width) * height > 1e9)
  {
    vtkErrorMacro("Bad image size " << width << " x " << height << ".");
    return 0;
  }
  const vtkIdType numPixels = static_cast<vtkIdType>(width) * height;
  const float* depth = nullptr;
  if (this->OpaqueDepth)
  {
    if (this->OpaqueDepth->GetNumberOfTuples() * this->OpaqueDepth->GetNumberOfComponents() !=
      numPixels)
    {
      vtkErrorMacro("The opaque depth has " << this->OpaqueDepth->GetNumberOfValues()
                                            << " values; the image has " << numPixels
                                            << " pixels.");
      return 0;
    }
    depth = this->OpaqueDepth->GetPointer(0);
  }

  // The mesh, prepared again only when what it depends on changed.
  double matrix[16];
  vtkMatrix4x4* m = this->Volume ? this->Volume->GetMatrix() : this->VolumeMatrix;
  vtkMatrix4x4::DeepCopy(matrix, m);
  // The one scalar the property takes from the selected array (the mapper's rule).
  int cellFlag = -1;
  vtkDataArray* array = vtkAbstractMapper::GetScalars(this->Input, this->ScalarMode,
    this->ArrayAccessMode, this->ArrayId, this->ArrayName, cellFlag);
  vtkNew<vtkTetScalarSelection> selection;
  selection->SetVectorMode(this->VectorMode);
  selection->SetVectorComponent(this->VectorComponent);
  if (array && !selection->Resolve(array->GetNumberOfComponents(), array->GetName(), property))
  {
    vtkErrorMacro("Not rendered: " << selection->GetErrorMessage() << ".");
    return 0;
  }
  const bool magnitude = selection->GetMagnitude();
  const int component = selection->GetComponent();
  bool fresh = in.Valid && in.Input == this->Input && in.InputMTime == this->Input->GetMTime() &&
    in.ScalarMode == this->ScalarMode && in.ArrayAccessMode == this->ArrayAccessMode &&
    in.ArrayId == this->ArrayId && in.ArrayName == (this->ArrayName ? this->ArrayName : "") &&
    in.Magnitude == magnitude && in.Component == component &&
    std::equal(matrix, matrix + 16, in.Matrix);
  if (!fresh)
  {
    vtkNew<vtkTimerLog> timer;
    timer->StartTimer();
    std::string error;
    vtkIdType degenerate = 0;
    if (!in.Prepare(this, this->Input, magnitude, component, matrix, degenerate, error))
    {
      vtkErrorMacro(<< error);
      return 0;
    }
    timer->StopTimer();
    this->LastPreparationTime = timer->GetElapsedTime();
    this->NumberOfTetrahedra = static_cast<vtkIdType>(in.Transparent.size());
    this->NumberOfDegenerateTetrahedra = degenerate;
    this->NumberOfOverlappingTetrahedra = static_cast<vtkIdType>(in.NumberOfOverlapping);
  }

  if (in.Property != property || in.PropertyMTime != property->GetMTime() ||
    !this->Integrator->IsInitialized())
  {
    if (!this->Integrator->Initialize(property))
    {
      vtkErrorMacro("The volume property cannot be integrated.");
      in.Property = nullptr;
      return 0;
    }
    in.Property = property;
    in.PropertyMTime = property->GetMTime();
  }

  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();

  // Clip coordinates of the camera to world coordinates.
  double inverse[16];
  vtkMatrix4x4::DeepCopy(inverse,
    this->Camera->GetCompositeProjectionTransformMatrix(
      static_cast<double>(width) / height, -1.0, 1.0));
  vtkMatrix4x4::Invert(inverse, inverse);
  const double* center = in.Center;
  // The clipping planes in the shifted world coordinates of the rays (n.x + d >= 0 is kept).
  std::vector<std::array<double, 4>> clipping;
  if (this->ClippingPlanes)
  {
    for (int k = 0; k < this->ClippingPlanes->GetNumberOfItems(); ++k)
    {
      vtkPlane* plane = this->ClippingPlanes->GetItem(k);
      std::array<double, 4> h;
      plane->GetNormal(h.data());
      double origin[3];
      plane->GetOrigin(origin);
      h[3] = 0.0;
      for (int r = 0; r < 3; ++r)
      {
        h[3] -= h[r] * (origin[r] - center[r]);
      }
      if (h[0] != 0.0 || h[1] != 0.0 || h[2] != 0.0)
      {
        clipping.push_back(h);
      }
    }
  }
  auto unproject = [&inverse, center](double x, double y, double z, double p[3])
  {
    double h[4];
    for (int r = 0; r < 4; ++r)
    {
      h[r] =
        inverse[4 * r] * x + inverse[4 * r + 1] * y + inverse[4 * r + 2] * z + inverse[4 * r + 3];
    }
    for (int r = 0; r < 3; ++r)
    {
      p[r] = h[r] / h[3] - center[r];
    }
  };

  vtkSmartPointer<vtkDataArray> rgba;
  if (this->DoublePrecisionOutput)
  {
    rgba = vtkSmartPointer<vtkDoubleArray>::New();
  }
  else
  {
    rgba = vtkSmartPointer<vtkFloatArray>::New();
  }
  rgba->SetName("RGBA");
  rgba->SetNumberOfComponents(4);
  rgba->SetNumberOfTuples(numPixels);
  vtkNew<vtkIntArray> counts;
  counts->SetName("NumberOfTets");
  counts->SetNumberOfTuples(numPixels);
  float* rgbaFloat =
    this->DoublePrecisionOutput ? nullptr : vtkFloatArray::SafeDownCast(rgba)->GetPointer(0);
  double* rgbaDouble =
    this->DoublePrecisionOutput ? vtkDoubleArray::SafeDownCast(rgba)->GetPointer(0) : nullptr;
  int* countOut = counts->GetPointer(0);
  const double offsetX = this->SampleOffset[0], offsetY = this->SampleOffset[1];
  vtkTetRayIntegrator* integrator = this->Integrator;

  vtkSMPTools::For(0, height, 1,
    [&](vtkIdType rowBegin, vtkIdType rowEnd)
    {
      std::vector<Hit>& hits = in.Hits.Local();
      for (vtkIdType j = rowBegin; j < rowEnd; ++j)
      {
        for (int i = 0; i < width; ++i)
        {
          const vtkIdType pixel = j * width + i;
          // Zero until a result is stored (rays that meet nothing leave early).
          auto store = [&](const double v[4])
          {
            for (int k = 0; k < 4; ++k)
            {
              if (rgbaFloat)
              {
                rgbaFloat[4 * pixel + k] = static_cast<float>(v[k]);
              }
              else
              {
                rgbaDouble[4 * pixel + k] = v[k];
              }
            }
          };
          const double zero[4] = { 0.0, 0.0, 0.0, 0.0 };
          store(zero);
          countOut[pixel] = 0;
          const double x = 2.0 * (i + offsetX) / width - 1.0;
          const double y = 2.0 * (j + offsetY) / height - 1.0;
          double nearP[3], farP[3], d[3];
          unproject(x, y, -1.0, nearP);
          unproject(x, y, 1.0, farP);
          for (int k = 0; k < 3; ++k)
          {
            d[k] = farP[k] - nearP[k];
          }
          const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
          if (!(dd > 0.0) || !std::isfinite(dd))
          {
            continue;
          }
          double lambdaMax = 1.0;
          if (depth && depth[pixel] < 1.0f)
          {
            double p[3];
            unproject(x, y, 2.0 * depth[pixel] - 1.0, p);
            lambdaMax =
              ((p[0] - nearP[0]) * d[0] + (p[1] - nearP[1]) * d[1] + (p[2] - nearP[2]) * d[2]) / dd;
            lambdaMax = std::min(1.0, std::max(0.0, lambdaMax));
          }
          // The kept half-spaces cut the ray to [lambdaMin, lambdaMax].
          double lambdaMin = 0.0;
          for (const std::array<double, 4>& h : clipping)
          {
            const double at0 = h[0] * nearP[0] + h[1] * nearP[1] + h[2] * nearP[2] + h[3];
            const double rate = h[0] * d[0] + h[1] * d[1] + h[2] * d[2];
            if (rate > 0.0)
            {
              lambdaMin = std::max(lambdaMin, -at0 / rate);
            }
            else if (rate < 0.0)
            {
              lambdaMax = std::min(lambdaMax, -at0 / rate);
            }
            else if (at0 < 0.0)
            {
              lambdaMax = -1.0;
            }
          }
          if (!(lambdaMax > 0.0) || !(lambdaMax > lambdaMin))
          {
            continue;
          }
          // Measure the ray from its point nearest to the mesh centre (the origin here): the
          // vertex coordinates of the ray frame then stay as small as the mesh.
          const double lambdaC = std::min(
            lambdaMax, std::max(0.0, -(nearP[0] * d[0] + nearP[1] * d[1] + nearP[2] * d[2]) / dd));
          double origin[3];
          for (int k = 0; k < 3; ++k)
          {
            origin[k] = nearP[k] + lambdaC * d[k];
          }
          in.CastRay(origin, d, lambdaMin - lambdaC, lambdaMax - lambdaC, hits);
          countOut[pixel] = static_cast<int>(hits.size());
          const double unitLength = std::sqrt(dd);
          double color[3] = { 0.0, 0.0, 0.0 };
          double opticalDepth = 0.0;
          for (const Hit& hit : hits)
          {
            if (in.Transparent[hit.Tet])
            {
              continue;
            }
            double segment[4], segmentDepth;
            integrator->IntegrateWithDepth(
              hit.S0, hit.S1, (hit.Z1 - hit.Z0) * unitLength, segment, &segmentDepth);
            const double transmittance = std::exp(-opticalDepth);
            for (int k = 0; k < 3; ++k)
            {
              color[k] += transmittance * segment[k];
            }
            opticalDepth += segmentDepth;
            if (opticalDepth > TerminationDepth)
            {
              break;
            }
          }
          const double result[4] = { color[0], color[1], color[2], -std::expm1(-opticalDepth) };
          store(result);
        }
      }
    });

  this->Output->SetDimensions(width, height, 1);
  this->Output->GetPointData()->SetScalars(rgba);
  this->Output->GetPointData()->AddArray(counts);
  timer->StopTimer();
  this->LastRayCastTime = timer->GetElapsedTime();
  return 1;
}

namespace
{
// The premultiplied RGBA scalars of `rgba`; null, with a warning naming the caller, when there are
// none or there is no output image.
vtkDataArray* RGBAScalars(const char* caller, vtkImageData* rgba, vtkImageData* output)
{
  vtkDataArray* in = rgba ? rgba->GetPointData()->GetScalars() : nullptr;
  if (!in || in->GetNumberOfComponents() != 4 || !output)
  {
    vtkGenericWarningMacro(<< caller << " needs an image with 4-component scalars.");
    return nullptr;
  }
  return in;
}

// `rgba` composited over `background` into `output`: 3-component "RGB" scalars of ArrayT, each
// composited value stored as convert(value).
template <typename ArrayT, typename Convert>
void CompositeInto(const char* caller, vtkImageData* rgba, const double background[3],
  vtkImageData* output, Convert convert)
{
  vtkDataArray* in = RGBAScalars(caller, rgba, output);
  if (!in)
  {
    return;
  }
  const vtkIdType n = in->GetNumberOfTuples();
  vtkNew<ArrayT> rgb;
  rgb->SetName("RGB");
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double a = in->GetComponent(i, 3);
    for (int k = 0; k < 3; ++k)
    {
      rgb->SetTypedComponent(i, k, convert(in->GetComponent(i, k) + (1.0 - a) * background[k]));
    }
  }
  output->Initialize();
  output->SetDimensions(rgba->GetDimensions());
  output->GetPointData()->SetScalars(rgb);
}
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::CompositeOverBackground(
  vtkImageData* rgba, const double background[3], vtkImageData* output)
{
  CompositeInto<vtkFloatArray>("CompositeOverBackground", rgba, background, output,
    [](double v) { return static_cast<float>(v); });
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::ConvertToUnsignedChar(
  vtkImageData* rgba, const double background[3], vtkImageData* output)
{
  CompositeInto<vtkUnsignedCharArray>("ConvertToUnsignedChar", rgba, background, output,
    [](double v)
    { return static_cast<unsigned char>(std::lround(255.0 * std::min(1.0, std::max(0.0, v)))); });
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::EmulateRayCastImageDisplay(
  vtkImageData* rgba, const double background[3], vtkImageData* output)
{
  vtkDataArray* in = RGBAScalars("EmulateRayCastImageDisplay", rgba, output);
  if (!in)
  {
    return;
  }
  int dims[3];
  rgba->GetDimensions(dims);
  const int w = dims[0], h = dims[1];
  // The 8-bit texture the mapper fills (it truncates).
  std::vector<double> texel(4 * static_cast<size_t>(w) * h);
  for (vtkIdType p = 0; p < static_cast<vtkIdType>(w) * h; ++p)
  {
    for (int k = 0; k < 4; ++k)
    {
      texel[4 * p + k] = std::min(255.0, std::max(0.0, std::floor(255.0 * in->GetComponent(p, k))));
    }
  }
  // Where screen pixel i samples the texture, in texels.
  auto locate = [](int i, int n, int& i0, int& i1, double& f)
  {
    const double pos = n > 1 ? (i + 0.5) * (n - 1) / n : 0.0;
    i0 = static_cast<int>(std::floor(pos));
    i1 = std::min(i0 + 1, n - 1);
    f = pos - i0;
  };
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetName("RGB");
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  for (int j = 0; j < h; ++j)
  {
    int j0, j1;
    double fy;
    locate(j, h, j0, j1, fy);
    for (int i = 0; i < w; ++i)
    {
      int i0, i1;
      double fx;
      locate(i, w, i0, i1, fx);
      double v[4];
      for (int k = 0; k < 4; ++k)
      {
        auto t = [&](int x, int y) { return texel[4 * (static_cast<size_t>(y) * w + x) + k]; };
        v[k] = ((1 - fy) * ((1 - fx) * t(i0, j0) + fx * t(i1, j0)) +
                 fy * ((1 - fx) * t(i0, j1) + fx * t(i1, j1))) /
          255.0;
      }
      for (int k = 0; k < 3; ++k)
      {
        const double c = std::min(1.0, std::max(0.0, v[k] + (1.0 - v[3]) * background[k]));
        rgb->SetTypedComponent(
          static_cast<vtkIdType>(j) * w + i, k, static_cast<unsigned char>(std::lround(255.0 * c)));
      }
    }
  }
  output->Initialize();
  output->SetDimensions(w, h, 1);
  output->GetPointData()->SetScalars(rgb);
}

//------------------------------------------------------------------------------
int vtkTetReferenceRenderer::CompareImages(vtkImageData* a, vtkImageData* b, double stats[3])
{
  stats[0] = stats[1] = stats[2] = 0.0;
  vtkDataArray* da = a ? a->GetPointData()->GetScalars() : nullptr;
  vtkDataArray* db = b ? b->GetPointData()->GetScalars() : nullptr;
  if (!da || !db || da->GetNumberOfTuples() != db->GetNumberOfTuples() ||
    da->GetNumberOfComponents() < 3 || db->GetNumberOfComponents() < 3)
  {
    vtkGenericWarningMacro("CompareImages needs two images of the same size with 3+ components.");
    return 0;
  }
  const double scaleA = vtkUnsignedCharArray::SafeDownCast(da) ? 1.0 : 255.0;
  const double scaleB = vtkUnsignedCharArray::SafeDownCast(db) ? 1.0 : 255.0;
  const vtkIdType n = da->GetNumberOfTuples();
  std::vector<double> diffs(3 * static_cast<size_t>(n));
  double sum = 0.0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      const double diff =
        std::fabs(scaleA * da->GetComponent(i, k) - scaleB * db->GetComponent(i, k));
      diffs[3 * i + k] = diff;
      sum += diff * diff;
    }
  }
  if (diffs.empty())
  {
    return 1;
  }
  stats[0] = std::sqrt(sum / static_cast<double>(diffs.size()));
  const size_t rank = static_cast<size_t>(std::ceil(0.999 * static_cast<double>(diffs.size()))) - 1;
  std::nth_element(diffs.begin(), diffs.begin() + rank, diffs.end());
  stats[1] = diffs[rank];
  stats[2] = *std::max_element(diffs.begin(), diffs.end());
  return 1;
}

//------------------------------------------------------------------------------
void vtkTetReferenceRenderer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Input: " << this->Input << "\n";
  os << indent << "ScalarMode: " << this->ScalarMode << "\n";
  os << indent << "ArrayAccessMode: " << this->ArrayAccessMode << "\n";
  os << indent << "ArrayId: " << this->ArrayId << "\n";
  os << indent << "ArrayName: " << (this->ArrayName ? this->ArrayName : "(none)") << "\n";
  os << indent << "VectorMode: " << this->VectorMode << "\n";
  os << indent << "VectorComponent: " << this->VectorComponent << "\n";
  os << indent << "VolumeProperty: " << this->VolumeProperty << "\n";
  os << indent << "Camera: " << this->Camera << "\n";
  os << indent << "ImageSize: " << this->ImageSize[0] << " x " << this->ImageSize[1] << "\n";
  os << indent << "Volume: " << this->Volume << "\n";
  os << indent << "OpaqueDepth: " << this->OpaqueDepth << "\n";
  os << indent << "ClippingPlanes: " << this->ClippingPlanes << "\n";
  os << indent << "SampleOffset: " << this->SampleOffset[0] << ", " << this->SampleOffset[1]
     << "\n";
  os << indent << "DoublePrecisionOutput: " << this->DoublePrecisionOutput << "\n";
  os << indent << "NumberOfTetrahedra: " << this->NumberOfTetrahedra << "\n";
  os << indent << "NumberOfDegenerateTetrahedra: " << this->NumberOfDegenerateTetrahedra << "\n";
  os << indent << "LastPreparationTime: " << this->LastPreparationTime << "\n";
  os << indent << "LastRayCastTime: " << this->LastRayCastTime << "\n";
  os << indent << "VolumeMatrix:\n";
  this->VolumeMatrix->PrintSelf(os, indent.GetNextIndent());
  os << indent << "Integrator:\n";
  this->Integrator->PrintSelf(os, indent.GetNextIndent());
}
