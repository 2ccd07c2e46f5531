/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshBuilder.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetMeshBuilder.h"

#include "vtkAbstractMapper.h"
#include "vtkArrayDispatch.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDataArrayRange.h"
#include "vtkDataSet.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTetMesh.h"
#include "vtkTetMeshOverlapRule.h"
#include "vtkTetMeshValidationReport.h"
#include "vtkTetScalarSelection.h"
#include "vtkTimerLog.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <mutex>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkTetMeshBuilder);

namespace
{
constexpr uint32_t NoNeighbor = vtkTetMesh::NoNeighbor;
// Neighbour words keep 2 bits for the face: a mesh holds at most 2^30 tetrahedra.
constexpr vtkIdType MaxTetrahedra = vtkIdType(1) << 30;

//------------------------------------------------------------------------------
// Splits [0, n) into `blocks` contiguous ranges processed in parallel, one call of f(block,
// begin, end) per block. Used where each block needs its own private slice of an output (the
// counting sorts), which a plain vtkSMPTools::For cannot promise.
template <typename F>
void ForBlocks(vtkIdType n, int blocks, F&& f)
{
  vtkSMPTools::For(0, blocks, 1,
    [&](vtkIdType b0, vtkIdType b1)
    {
      for (vtkIdType b = b0; b < b1; ++b)
      {
        f(static_cast<int>(b), n * b / blocks, n * (b + 1) / blocks);
      }
    });
}

int NumberOfBlocks(vtkIdType work)
{
  const int threads = std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads());
  // A few blocks per thread balance the load; tiny inputs are not worth splitting.
  const vtkIdType byWork = std::max<vtkIdType>(1, work / 16384);
  return static_cast<int>(std::min<vtkIdType>({ byWork, 4 * threads, 64 }));
}

//------------------------------------------------------------------------------
// The dimension of a cell type, and whether vtkDataSetTriangleFilter can split it.
enum class CellKind
{
  Tetra,
  Split,      // a 3D cell that vtkDataSetTriangleFilter splits into tetrahedra
  LowerDim,   // vertices, lines, polygons: no volume
  Unsupported // 3D types VTK cannot instantiate (abstract higher-order, parametric)
};

CellKind ClassifyCellType(int type)
{
  switch (type)
  {
    case VTK_TETRA:
      return CellKind::Tetra;
    case VTK_VOXEL:
    case VTK_HEXAHEDRON:
    case VTK_WEDGE:
    case VTK_PYRAMID:
    case VTK_PENTAGONAL_PRISM:
    case VTK_HEXAGONAL_PRISM:
    case VTK_QUADRATIC_TETRA:
    case VTK_QUADRATIC_HEXAHEDRON:
    case VTK_QUADRATIC_WEDGE:
    case VTK_QUADRATIC_PYRAMID:
    case VTK_TRIQUADRATIC_HEXAHEDRON:
    case VTK_TRIQUADRATIC_PYRAMID:
    case VTK_QUADRATIC_LINEAR_WEDGE:
    case VTK_BIQUADRATIC_QUADRATIC_WEDGE:
    case VTK_BIQUADRATIC_QUADRATIC_HEXAHEDRON:
    case VTK_CONVEX_POINT_SET:
    case VTK_POLYHEDRON:
    case VTK_LAGRANGE_TETRAHEDRON:
    case VTK_LAGRANGE_HEXAHEDRON:
    case VTK_LAGRANGE_WEDGE:
    case VTK_LAGRANGE_PYRAMID:
    case VTK_BEZIER_TETRAHEDRON:
    case VTK_BEZIER_HEXAHEDRON:
    case VTK_BEZIER_WEDGE:
    case VTK_BEZIER_PYRAMID:
      return CellKind::Split;
    case VTK_PARAMETRIC_TETRA_REGION:
    case VTK_PARAMETRIC_HEX_REGION:
    case VTK_HIGHER_ORDER_TETRAHEDRON:
    case VTK_HIGHER_ORDER_WEDGE:
    case VTK_HIGHER_ORDER_PYRAMID:
    case VTK_HIGHER_ORDER_HEXAHEDRON:
      return CellKind::Unsupported;
    default:
      return CellKind::LowerDim;
  }
}

//------------------------------------------------------------------------------
// Point coordinates of any real or integer type into doubles.
struct CopyPointsWorker
{
  template <typename ArrayT>
  void operator()(ArrayT* array, double* out) const
  {
    const auto values = vtk::DataArrayValueRange<3>(array);
    const vtkIdType n = array->GetNumberOfTuples();
    vtkSMPTools::For(0, n, 8192,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = 3 * begin; i < 3 * end; ++i)
        {
          out[i] = static_cast<double>(values[i]);
        }
      });
  }
};

//------------------------------------------------------------------------------
// Sorted face of three point ids, for matching: bucketed by the smallest id, keyed by the
// other two. 12 bytes: the entries of a million tetrahedra take 48 MB, and on a virtual
// machine first touching fresh pages costs more than sorting them.
struct FaceEntry
{
  uint32_t Mid;
  uint32_t Hi;
  uint32_t Face; // (t << 2) | i
};

inline bool FaceEntryLess(const FaceEntry& a, const FaceEntry& b)
{
  if (a.Mid != b.Mid)
  {
    return a.Mid < b.Mid;
  }
  if (a.Hi != b.Hi)
  {
    return a.Hi < b.Hi;
  }
  return a.Face < b.Face;
}

inline bool SameFace(const FaceEntry& a, const FaceEntry& b)
{
  return a.Mid == b.Mid && a.Hi == b.Hi;
}

// Calls f(face, lo, mid, hi) for the four faces of a tetrahedron, lo < mid < hi; faces with a
// repeated point id (collapsed, zero area) are skipped.
template <typename F>
inline void ForEachSortedFace(const uint32_t* ids, uint32_t tet, F&& f)
{
  uint32_t v[4] = { ids[0], ids[1], ids[2], ids[3] };
  uint32_t l[4] = { 0, 1, 2, 3 };
  // Five compare-exchanges sort four values.
  auto cx = [&](int a, int b)
  {
    if (v[b] < v[a])
    {
      std::swap(v[a], v[b]);
      std::swap(l[a], l[b]);
    }
  };
  cx(0, 1);
  cx(2, 3);
  cx(0, 2);
  cx(1, 3);
  cx(1, 2);
  const uint32_t base = tet << 2;
  // Face opposite the point at sorted position k holds the other three, still sorted.
  if (v[1] != v[2] && v[2] != v[3])
  {
    f(base | l[0], v[1], v[2], v[3]);
  }
  if (v[0] != v[2] && v[2] != v[3])
  {
    f(base | l[1], v[0], v[2], v[3]);
  }
  if (v[0] != v[1] && v[1] != v[3])
  {
    f(base | l[2], v[0], v[1], v[3]);
  }
  if (v[0] != v[1] && v[1] != v[2])
  {
    f(base | l[3], v[0], v[1], v[2]);
  }
}

// Whether the outward order of a face is an even permutation of its sorted ids. Two
// positively oriented tetrahedra on opposite sides of a face see it with opposite parities.
inline bool FaceParity(const uint32_t* tetPoints, uint32_t face)
{
  const uint32_t* ids = tetPoints + 4 * static_cast<size_t>(face >> 2);
  const int* fp = vtkTetMesh::FacePoints[face & 3u];
  const uint32_t a = ids[fp[0]], b = ids[fp[1]], c = ids[fp[2]];
  // Rotate the smallest first; the order is even iff the next one is the middle value.
  if (a < b && a < c)
  {
    return b < c;
  }
  if (b < a && b < c)
  {
    return c < a;
  }
  return a < b;
}

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
// A vtkTimerLog event for the lifetime of the object (a no-op unless logging is on).
class ScopedEvent
{
public:
  explicit ScopedEvent(const char* name)
    : Name(name)
  {
    vtkTimerLog::MarkStartEvent(name);
  }
  ~ScopedEvent() { vtkTimerLog::MarkEndEvent(this->Name); }
  ScopedEvent(const ScopedEvent&) = delete;
  ScopedEvent& operator=(const ScopedEvent&) = delete;

private:
  const char* Name;
};

//------------------------------------------------------------------------------
// Build() reports its progress as vtkAlgorithm::UpdateProgress does: a ProgressEvent whose call
// data is a double* fraction in [0, 1]. The fractions reached after each phase of a full build
// follow the time each phase takes (docs/mesh-layout.md, post_tets6 and bracket): reading the
// points and cells 10 %, orientation 20 %, face matching 55 %, duplicates and cracks 10 %,
// scalars the rest.
void ReportProgress(vtkObject* builder, double fraction)
{
  builder->InvokeEvent(vtkCommand::ProgressEvent, &fraction);
}

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

//------------------------------------------------------------------------------
// What identifies one part of the input: the object (compared by address only, never
// dereferenced), its modification time and its size. Modification times are unique across all
// VTK objects, so a new object at a recycled address still reads as changed; the size catches
// cells or values appended without a Modified() call (InsertNextCell does not call it).
struct Stamp
{
  const void* Object = nullptr;
  vtkMTimeType MTime = 0;
  vtkIdType Size = 0;
  bool operator==(const Stamp& o) const
  {
    return this->Object == o.Object && this->MTime == o.MTime && this->Size == o.Size;
  }
  bool operator!=(const Stamp& o) const { return !(*this == o); }
};

Stamp MakeStamp(vtkObject* object, vtkIdType size = 0)
{
  Stamp s;
  s.Object = object;
  s.MTime = object ? object->GetMTime() : 0;
  s.Size = size;
  return s;
}

Stamp MakeStamp(vtkAbstractArray* array)
{
  return MakeStamp(array, array ? array->GetNumberOfValues() : 0);
}
}

//------------------------------------------------------------------------------
class vtkTetMeshBuilder::vtkInternals
{
public:
  vtkNew<vtkTetMesh> Mesh;

  // What the mesh was built from.
  bool Valid = false;
  const void* Input = nullptr;
  std::vector<Stamp> TopologyStamps;
  Stamp PointsStamp;
  vtkIdType NumberOfPoints = -1;
  Stamp ScalarsStamp;
  int ScalarsCellFlag = -1;
  // Settings the mesh was built with.
  bool SpatialOrdering = false;
  double DegeneracyTolerance = 0.0;
  int ScalarMode = 0;
  int ArrayAccessMode = 0;
  int ArrayId = -1;
  std::string ArrayName;
  int VectorMode = 0;
  int VectorComponent = 0;

  // Findings, kept across partial rebuilds.
  vtkIdType NumberOfInputCells = 0;
  vtkIdType NumberOfSplitCells = 0;
  vtkIdType NumberOfIgnoredCells = 0;
  vtkIdType NumberOfInvalidCells = 0;
  vtkIdType NumberOfInvertedTetrahedra = 0;
  vtkIdType NumberOfDegenerateTetrahedra = 0;
  vtkIdType NumberOfNonManifoldFaces = 0;
  vtkIdType NumberOfOverlappingTetrahedra = 0;
  vtkIdType NumberOfCrackFaces = 0;
  vtkIdType NumberOfDuplicatePoints = 0;
  vtkIdType NumberOfNonFiniteScalars = 0;
  std::vector<vtkIdType> DegenerateCellIds;
  std::string TopologyError;
  std::string ScalarError;

  // The scalar values per input cell (cell scalars only), before mapping to tetrahedra.
  std::vector<double> InputCellScalars;

  // Scratch space of the face matching, kept between builds: allocating (and first touching)
  // tens of megabytes anew costs more than the matching itself.
  std::vector<FaceEntry> FaceEntries;
  std::vector<uint32_t> FaceCounts;
  std::vector<uint64_t> BucketStarts;
  std::vector<uint8_t> FaceSides; // face matching: the parity of each face, 4 bits per tet
  // Likewise for the spatial sort (the permuted arrays are swapped with the mesh's).
  std::vector<uint64_t> SortKeys;
  std::vector<uint64_t> SortScratch;
  std::vector<uint32_t> SortTetPoints;
  std::vector<uint32_t> SortCellIds;
  // Likewise for duplicate points.
  std::vector<uint32_t> PointBuckets;
  std::vector<uint32_t> PointBucketStarts;
  std::vector<uint32_t> PointOrder;
  std::vector<uint32_t> Canonical;

  void GetTopologyStamps(vtkDataSet* input, std::vector<Stamp>& stamps)
  {
    stamps.clear();
    if (auto* ug = vtkUnstructuredGrid::SafeDownCast(input))
    {
      vtkCellArray* cells = ug->GetCells();
      stamps.push_back(MakeStamp(cells, cells ? cells->GetNumberOfCells() : 0));
      if (cells)
      {
        stamps.push_back(MakeStamp(cells->GetOffsetsArray()));
        stamps.push_back(MakeStamp(cells->GetConnectivityArray()));
      }
      stamps.push_back(MakeStamp(ug->GetCellTypesArray()));
      stamps.push_back(MakeStamp(ug->GetFaces()));
      stamps.push_back(MakeStamp(ug->GetFaceLocations()));
    }
    else if (input)
    {
      // No finer detail to go on: the data set's own time (not its arrays').
      Stamp s;
      s.Object = input;
      s.MTime = input->vtkObject::GetMTime();
      s.Size = input->GetNumberOfCells();
      stamps.push_back(s);
    }
  }

  static Stamp GetPointsStamp(vtkDataSet* input)
  {
    auto* pointSet = vtkPointSet::SafeDownCast(input);
    if (pointSet && pointSet->GetPoints())
    {
      return MakeStamp(pointSet->GetPoints(), pointSet->GetPoints()->GetNumberOfPoints());
    }
    // Implicit points (image data, rectilinear grids) belong to the topology stamp.
    return Stamp();
  }

  void ReportTo(vtkTetMeshValidationReport* report, vtkDataSet* input)
  {
    report->Reset();
    vtkTetMesh* mesh = this->Mesh;
    report->SetNumberOfInputPoints(input ? input->GetNumberOfPoints() : 0);
    report->SetNumberOfInputCells(this->NumberOfInputCells);
    report->SetNumberOfTetrahedra(mesh->GetNumberOfTetrahedra());
    report->SetNumberOfBoundaryFaces(mesh->GetNumberOfBoundaryFaces());
    report->SetNumberOfSplitCells(this->NumberOfSplitCells);
    report->SetNumberOfIgnoredCells(this->NumberOfIgnoredCells);
    report->SetNumberOfInvalidCells(this->NumberOfInvalidCells);
    report->SetNumberOfInvertedTetrahedra(this->NumberOfInvertedTetrahedra);
    report->SetNumberOfDegenerateTetrahedra(this->NumberOfDegenerateTetrahedra);
    report->SetNumberOfNonManifoldFaces(this->NumberOfNonManifoldFaces);
    report->SetNumberOfOverlappingTetrahedra(this->NumberOfOverlappingTetrahedra);
    report->SetNumberOfCrackFaces(this->NumberOfCrackFaces);
    report->SetNumberOfDuplicatePoints(this->NumberOfDuplicatePoints);
    report->SetNumberOfNonFiniteScalars(this->NumberOfNonFiniteScalars);
    vtkIdTypeArray* ids = report->GetDegenerateCellIds();
    ids->SetNumberOfValues(static_cast<vtkIdType>(this->DegenerateCellIds.size()));
    std::copy(this->DegenerateCellIds.begin(), this->DegenerateCellIds.end(), ids->GetPointer(0));
    if (!this->TopologyError.empty())
    {
      report->SetError(this->TopologyError);
    }
    else if (!this->ScalarError.empty())
    {
      report->SetError(this->ScalarError);
    }
  }

  template <typename T>
  static size_t Bytes(const std::vector<T>& v)
  {
    return v.capacity() * sizeof(T);
  }
  template <typename T>
  static void Free(std::vector<T>& v)
  {
    std::vector<T>().swap(v);
  }

  vtkIdType ScratchSize() const
  {
    return static_cast<vtkIdType>(Bytes(this->FaceEntries) + Bytes(this->FaceCounts) +
      Bytes(this->BucketStarts) + Bytes(this->FaceSides) + Bytes(this->SortKeys) + Bytes(this->SortScratch) +
      Bytes(this->SortTetPoints) + Bytes(this->SortCellIds) + Bytes(this->PointBuckets) +
      Bytes(this->PointBucketStarts) + Bytes(this->PointOrder) + Bytes(this->Canonical));
  }

  void ReleaseScratch()
  {
    Free(this->FaceEntries);
    Free(this->FaceCounts);
    Free(this->BucketStarts);
    Free(this->FaceSides);
    Free(this->SortKeys);
    Free(this->SortScratch);
    Free(this->SortTetPoints);
    Free(this->SortCellIds);
    Free(this->PointBuckets);
    Free(this->PointBucketStarts);
    Free(this->PointOrder);
    Free(this->Canonical);
  }

  bool ReadPoints(vtkDataSet* input, std::string& error);
  void ComputeBounds();
  bool ExtractTetrahedra(vtkDataSet* input, std::string& error, vtkIdType& numTetsFromSplit);
  void SortSpatially();
  bool OrientAndClassify(double tolerance, bool allowFlips);
  void MatchFaces();
  void OrientDegenerateTetrahedra();
  void CollectBoundaryFaces();
  void FindDuplicatesAndCracks();
  bool ReadScalars(vtkDataSet* input, vtkTetMeshBuilder* self, std::string& error);
  void FlagNonFiniteTets();
};

//------------------------------------------------------------------------------
bool vtkTetMeshBuilder::vtkInternals::ReadPoints(vtkDataSet* input, std::string& error)
{
  vtkTetMesh* mesh = this->Mesh;
  const vtkIdType n = input->GetNumberOfPoints();
  mesh->Points.resize(3 * static_cast<size_t>(n));
  double* out = mesh->Points.data();
  auto* pointSet = vtkPointSet::SafeDownCast(input);
  vtkDataArray* data =
    pointSet && pointSet->GetPoints() ? pointSet->GetPoints()->GetData() : nullptr;
  if (data && data->GetNumberOfComponents() == 3 && data->GetNumberOfTuples() == n)
  {
    CopyPointsWorker worker;
    if (!vtkArrayDispatch::Dispatch::Execute(data, worker, out))
    {
      worker(data, out);
    }
  }
  else
  {
    // Implicit points (image data, rectilinear grids): ask the data set.
    for (vtkIdType i = 0; i < n; ++i)
    {
      input->GetPoint(i, out + 3 * i);
    }
  }
  // Coordinates that are NaN or infinite have no place in space: nothing sensible can be
  // drawn from them, and they would break the sorts below.
  std::atomic<vtkIdType> bad(0);
  vtkSMPTools::For(0, 3 * n, 65536,
    [&](vtkIdType begin, vtkIdType end)
    {
      vtkIdType count = 0;
      for (vtkIdType i = begin; i < end; ++i)
      {
        count += std::isfinite(out[i]) ? 0 : 1;
      }
      bad += count;
    });
  if (bad > 0)
  {
    std::ostringstream text;
    text << bad.load() << " point coordinates are NaN or infinite";
    error = text.str();
    return false;
  }
  this->ComputeBounds();
  return true;
}

//------------------------------------------------------------------------------
void vtkTetMeshBuilder::vtkInternals::ComputeBounds()
{
  vtkTetMesh* mesh = this->Mesh;
  const vtkIdType n = mesh->GetNumberOfPoints();
  const double* p = mesh->Points.data();
  const int blocks = NumberOfBlocks(n);
  std::vector<double> partial(6 * static_cast<size_t>(blocks));
  ForBlocks(n, blocks,
    [&](int b, vtkIdType begin, vtkIdType end)
    {
      double bb[6] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX,
        VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
      for (vtkIdType i = begin; i < end; ++i)
      {
        for (int c = 0; c < 3; ++c)
        {
          bb[2 * c] = std::min(bb[2 * c], p[3 * i + c]);
          bb[2 * c + 1] = std::max(bb[2 * c + 1], p[3 * i + c]);
        }
      }
      std::copy(bb, bb + 6, partial.begin() + 6 * b);
    });
  double bounds[6] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX,
    VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (int b = 0; b < blocks; ++b)
  {
    for (int c = 0; c < 3; ++c)
    {
      bounds[2 * c] = std::min(bounds[2 * c], partial[6 * b + 2 * c]);
      bounds[2 * c + 1] = std::max(bounds[2 * c + 1], partial[6 * b + 2 * c + 1]);
    }
  }
  if (n == 0)
  {
    const double empty[6] = { 0.0, -1.0, 0.0, -1.0, 0.0, -1.0 };
    std::copy(empty, empty + 6, bounds);
  }
  std::copy(bounds, bounds + 6, mesh->Bounds);
  for (int c = 0; c < 3; ++c)
  {
    mesh->Shift[c] = n == 0 ? 0.0 : 0.5 * (bounds[2 * c] + bounds[2 * c + 1]);
  }
}

//------------------------------------------------------------------------------
bool vtkTetMeshBuilder::vtkInternals::ExtractTetrahedra(
  vtkDataSet* input, std::string& error, vtkIdType& numTetsFromSplit)
{
  vtkTetMesh* mesh = this->Mesh;
  const vtkIdType numPoints = input->GetNumberOfPoints();
  const vtkIdType numCells = input->GetNumberOfCells();
  std::vector<uint32_t>& tetPoints = mesh->TetPoints;
  std::vector<uint32_t>& cellIds = mesh->TetInputCellIds;
  tetPoints.clear();
  cellIds.clear();
  numTetsFromSplit = 0;

  // Cells to split, gathered into a grid that shares our points.
  vtkNew<vtkUnstructuredGrid> toSplit;
  vtkNew<vtkIdTypeArray> toSplitIds;
  toSplitIds->SetName("vtkTetMeshBuilderCellIds");
  toSplit->Allocate(64);
  vtkNew<vtkIdList> ptIds;

  auto validIds = [numPoints](const vtkIdType* ids, vtkIdType n)
  {
    for (vtkIdType k = 0; k < n; ++k)
    {
      if (ids[k] < 0 || ids[k] >= numPoints)
      {
        return false;
      }
    }
    return true;
  };
  auto addTet = [&](const vtkIdType* ids, vtkIdType cellId)
  {
    for (int k = 0; k < 4; ++k)
    {
      tetPoints.push_back(static_cast<uint32_t>(ids[k]));
    }
    cellIds.push_back(static_cast<uint32_t>(cellId));
  };
  auto addToSplit = [&](int type, vtkIdList* ids, vtkIdType cellId)
  {
    toSplit->InsertNextCell(type, ids);
    toSplitIds->InsertNextValue(cellId);
  };

  auto* ug = vtkUnstructuredGrid::SafeDownCast(input);
  vtkCellArray* cells = ug ? ug->GetCells() : nullptr;
  vtkUnsignedCharArray* types = ug ? ug->GetCellTypesArray() : nullptr;
  if (ug && cells && types && types->GetNumberOfValues() >= numCells)
  {
    const unsigned char* typePtr = types->GetPointer(0);
    // The common case, all linear tetrahedra: a parallel copy of the connectivity.
    bool allTets = cells->GetNumberOfConnectivityIds() == 4 * numCells;
    for (vtkIdType c = 0; c < numCells && allTets; ++c)
    {
      allTets = typePtr[c] == VTK_TETRA;
    }
    if (allTets)
    {
      tetPoints.resize(4 * static_cast<size_t>(numCells));
      cellIds.resize(static_cast<size_t>(numCells));
      std::atomic<vtkIdType> invalid(0);
      // Bad point ids or irregular offsets send the grid to the cell-by-cell path below.
      auto copy = [&](auto* conn, auto* offsets)
      {
        vtkSMPTools::For(0, numCells, 16384,
          [&](vtkIdType begin, vtkIdType end)
          {
            vtkIdType bad = 0;
            for (vtkIdType c = begin; c < end; ++c)
            {
              bad += static_cast<vtkIdType>(offsets[c]) != 4 * c ? 1 : 0;
              for (int k = 0; k < 4; ++k)
              {
                const vtkIdType id = static_cast<vtkIdType>(conn[4 * c + k]);
                bad += (id < 0 || id >= numPoints) ? 1 : 0;
                tetPoints[4 * c + k] = static_cast<uint32_t>(id);
              }
              cellIds[c] = static_cast<uint32_t>(c);
            }
            invalid += bad;
          });
      };
      if (cells->IsStorage64Bit())
      {
        copy(cells->GetConnectivityArray64()->GetPointer(0),
          cells->GetOffsetsArray64()->GetPointer(0));
      }
      else
      {
        copy(cells->GetConnectivityArray32()->GetPointer(0),
          cells->GetOffsetsArray32()->GetPointer(0));
      }
      if (invalid == 0)
      {
        return true;
      }
      // Rare: fall through to the cell-by-cell path, which drops the bad cells.
      tetPoints.clear();
      cellIds.clear();
    }

    tetPoints.reserve(4 * static_cast<size_t>(numCells));
    cellIds.reserve(static_cast<size_t>(numCells));
    vtkIdType npts;
    const vtkIdType* pts;
    for (vtkIdType c = 0; c < numCells; ++c)
    {
      const int type = typePtr[c];
      const CellKind kind = ClassifyCellType(type);
      if (kind == CellKind::LowerDim || kind == CellKind::Unsupported)
      {
        ++this->NumberOfIgnoredCells;
        continue;
      }
      if (type == VTK_POLYHEDRON)
      {
        ug->GetFaceStream(c, ptIds);
        // The stream interleaves counts and ids: check the ids face by face.
        bool ok = ptIds->GetNumberOfIds() > 0;
        vtkIdType pos = 1;
        for (vtkIdType f = 0; ok && f < ptIds->GetId(0); ++f)
        {
          const vtkIdType nf = ptIds->GetId(pos);
          ok = nf >= 3 && pos + 1 + nf <= ptIds->GetNumberOfIds() &&
            validIds(ptIds->GetPointer(pos + 1), nf);
          pos += 1 + nf;
        }
        if (!ok)
        {
          ++this->NumberOfInvalidCells;
          continue;
        }
        addToSplit(type, ptIds, c);
        continue;
      }
      cells->GetCellAtId(c, npts, pts);
      if (!validIds(pts, npts) || (kind == CellKind::Tetra && npts != 4))
      {
        ++this->NumberOfInvalidCells;
        continue;
      }
      if (kind == CellKind::Tetra)
      {
        addTet(pts, c);
      }
      else
      {
        ptIds->SetNumberOfIds(npts);
        std::copy(pts, pts + npts, ptIds->GetPointer(0));
        addToSplit(type, ptIds, c);
      }
    }
  }
  else
  {
    // Any other data set, one cell at a time.
    for (vtkIdType c = 0; c < numCells; ++c)
    {
      const int type = input->GetCellType(c);
      const CellKind kind = ClassifyCellType(type);
      if (kind == CellKind::LowerDim || kind == CellKind::Unsupported ||
        type == VTK_POLYHEDRON) // needs a face stream, which only vtkUnstructuredGrid gives
      {
        ++this->NumberOfIgnoredCells;
        continue;
      }
      input->GetCellPoints(c, ptIds);
      const vtkIdType npts = ptIds->GetNumberOfIds();
      if (!validIds(ptIds->GetPointer(0), npts) || (kind == CellKind::Tetra && npts != 4))
      {
        ++this->NumberOfInvalidCells;
        continue;
      }
      if (kind == CellKind::Tetra)
      {
        addTet(ptIds->GetPointer(0), c);
      }
      else
      {
        addToSplit(type, ptIds, c);
      }
    }
  }

  this->NumberOfSplitCells = toSplit->GetNumberOfCells();
  if (this->NumberOfSplitCells > 0)
  {
    // The points are ours (double precision, same ids), wrapped without a copy.
    vtkNew<vtkDoubleArray> coordinates;
    coordinates->SetNumberOfComponents(3);
    coordinates->SetArray(mesh->Points.data(), static_cast<vtkIdType>(mesh->Points.size()), 1);
    vtkNew<vtkPoints> points;
    points->SetData(coordinates);
    toSplit->SetPoints(points);
    toSplit->GetCellData()->AddArray(toSplitIds);

    vtkNew<vtkDataSetTriangleFilter> splitter;
    splitter->SetInputData(toSplit);
    splitter->TetrahedraOnlyOn();
    splitter->Update();
    vtkUnstructuredGrid* tets = splitter->GetOutput();
    auto* origin =
      vtkIdTypeArray::SafeDownCast(tets->GetCellData()->GetArray("vtkTetMeshBuilderCellIds"));
    if (!origin || origin->GetNumberOfValues() != tets->GetNumberOfCells())
    {
      error = "splitting the non-tetrahedral cells failed";
      return false;
    }
    vtkIdType npts;
    const vtkIdType* pts;
    for (vtkIdType c = 0; c < tets->GetNumberOfCells(); ++c)
    {
      tets->GetCellPoints(c, npts, pts);
      if (tets->GetCellType(c) == VTK_TETRA && npts == 4 && validIds(pts, 4))
      {
        addTet(pts, origin->GetValue(c));
        ++numTetsFromSplit;
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTetMeshBuilder::vtkInternals::SortSpatially()
{
  vtkTetMesh* mesh = this->Mesh;
  const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
  const double* p = mesh->Points.data();
  const uint32_t* tp = mesh->TetPoints.data();
  double origin[3], scale[3];
  for (int c = 0; c < 3; ++c)
  {
    origin[c] = mesh->Bounds[2 * c];
    const double extent = mesh->Bounds[2 * c + 1] - mesh->Bounds[2 * c];
    scale[c] = extent > 0.0 ? 2047.0 / extent : 0.0;
  }
  // One 64-bit key per tetrahedron: 33 bits of Morton code above the 30-bit tetrahedron id.
  std::vector<uint64_t>& keys = this->SortKeys;
  keys.resize(static_cast<size_t>(numTets));
  vtkSMPTools::For(0, numTets, 16384,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType t = begin; t < end; ++t)
      {
        uint64_t code = 0;
        for (int c = 0; c < 3; ++c)
        {
          const double centroid = 0.25 *
            (p[3 * tp[4 * t] + c] + p[3 * tp[4 * t + 1] + c] + p[3 * tp[4 * t + 2] + c] +
              p[3 * tp[4 * t + 3] + c]);
          const double q = std::min(2047.0, std::max(0.0, (centroid - origin[c]) * scale[c]));
          code |= SpreadBits3(static_cast<uint64_t>(q)) << c;
        }
        keys[t] = (code << 30) | static_cast<uint64_t>(t);
      }
    });
  // Three stable counting passes of 11 bits over the code (least significant first): linear,
  // and ties stay in input order.
  std::vector<uint64_t>& scratch = this->SortScratch;
  scratch.resize(keys.size());
  for (int shift = 30; shift < 63; shift += 11)
  {
    size_t position[2048] = { 0 };
    for (uint64_t key : keys)
    {
      ++position[(key >> shift) & 2047];
    }
    size_t running = 0;
    for (size_t& slot : position)
    {
      const size_t n = slot;
      slot = running;
      running += n;
    }
    for (uint64_t key : keys)
    {
      scratch[position[(key >> shift) & 2047]++] = key;
    }
    keys.swap(scratch);
  }
  std::vector<uint32_t>& tetPoints = this->SortTetPoints;
  std::vector<uint32_t>& cellIds = this->SortCellIds;
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
// Orientation and degeneracy of every tetrahedron. With allowFlips false (a points-only
// update) nothing is reoriented: returns false as soon as a tetrahedron would need it.
bool vtkTetMeshBuilder::vtkInternals::OrientAndClassify(double tolerance, bool allowFlips)
{
  vtkTetMesh* mesh = this->Mesh;
  const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
  const double* p = mesh->Points.data();
  uint32_t* tp = mesh->TetPoints.data();
  mesh->TetFlags.resize(static_cast<size_t>(numTets));
  uint8_t* flags = mesh->TetFlags.data();
  std::atomic<bool> needsFlip(false);
  vtkSMPTools::For(0, numTets, 16384,
    [&](vtkIdType begin, vtkIdType end)
    {
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
  // Counts and the input cells of degenerate tetrahedra (a serial pass over bytes).
  vtkIdType inverted = 0;
  this->DegenerateCellIds.clear();
  for (vtkIdType t = 0; t < numTets; ++t)
  {
    inverted += (flags[t] & vtkTetMesh::Inverted) ? 1 : 0;
    if (flags[t] & vtkTetMesh::Degenerate)
    {
      this->DegenerateCellIds.push_back(mesh->TetInputCellIds[t]);
    }
  }
  this->NumberOfDegenerateTetrahedra = static_cast<vtkIdType>(this->DegenerateCellIds.size());
  std::sort(this->DegenerateCellIds.begin(), this->DegenerateCellIds.end());
  this->DegenerateCellIds.erase(
    std::unique(this->DegenerateCellIds.begin(), this->DegenerateCellIds.end()),
    this->DegenerateCellIds.end());
  if (allowFlips)
  {
    this->NumberOfInvertedTetrahedra = inverted;
  }
  return true;
}

//------------------------------------------------------------------------------
// Face adjacency without a hash map: faces are bucketed by their smallest point id with a
// parallel counting sort (each block of tetrahedra owns its slice of every bucket, so no
// atomics), then each bucket, a few dozen faces on average, is sorted by its two other ids and
// scanned for runs of equal faces.
void vtkTetMeshBuilder::vtkInternals::MatchFaces()
{
  vtkTetMesh* mesh = this->Mesh;
  const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
  const size_t numPoints = static_cast<size_t>(mesh->GetNumberOfPoints());
  const uint32_t* tp = mesh->TetPoints.data();
  mesh->TetNeighbors.assign(4 * static_cast<size_t>(numTets), NoNeighbor);
  uint32_t* neighbors = mesh->TetNeighbors.data();

  // Per-block counters cost blocks * numPoints words: keep that below the faces themselves.
  int blocks = NumberOfBlocks(numTets);
  const size_t maxBlocks =
    std::max<size_t>(1, 4 * static_cast<size_t>(numTets) / std::max<size_t>(1, numPoints));
  blocks = static_cast<int>(std::min<size_t>(static_cast<size_t>(blocks), maxBlocks));

  std::vector<uint32_t>& counts = this->FaceCounts;
  counts.assign(static_cast<size_t>(blocks) * numPoints, 0u);
  ForBlocks(numTets, blocks,
    [&](int b, vtkIdType begin, vtkIdType end)
    {
      uint32_t* count = counts.data() + static_cast<size_t>(b) * numPoints;
      for (vtkIdType t = begin; t < end; ++t)
      {
        ForEachSortedFace(tp + 4 * t, static_cast<uint32_t>(t),
          [&](uint32_t, uint32_t lo, uint32_t, uint32_t) { ++count[lo]; });
      }
    });
  // Exclusive prefix sums: bucket starts, and each block's write position inside them.
  std::vector<uint64_t>& start = this->BucketStarts;
  start.resize(numPoints + 1);
  uint64_t running = 0;
  for (size_t v = 0; v < numPoints; ++v)
  {
    start[v] = running;
    for (int b = 0; b < blocks; ++b)
    {
      // Absolute positions: 4 * 2^30 faces at most, so they fit 32 bits.
      uint32_t& c = counts[static_cast<size_t>(b) * numPoints + v];
      const uint32_t n = c;
      c = static_cast<uint32_t>(running);
      running += n;
    }
  }
  start[numPoints] = running;
  if (this->FaceEntries.size() < running)
  {
    this->FaceEntries.resize(static_cast<size_t>(running));
  }
  FaceEntry* entries = this->FaceEntries.data();
  // The side of each face (bit i of a tetrahedron's byte: FaceParity of face i), while its
  // points are in cache: matching then tells overlapping pairs apart without reading them.
  this->FaceSides.resize(static_cast<size_t>(numTets));
  uint8_t* sides = this->FaceSides.data();
  ForBlocks(numTets, blocks,
    [&](int b, vtkIdType begin, vtkIdType end)
    {
      uint32_t* offset = counts.data() + static_cast<size_t>(b) * numPoints;
      for (vtkIdType t = begin; t < end; ++t)
      {
        uint8_t side = 0;
        ForEachSortedFace(tp + 4 * t, static_cast<uint32_t>(t),
          [&](uint32_t face, uint32_t lo, uint32_t mid, uint32_t hi)
          {
            FaceEntry& e = entries[offset[lo]++];
            e.Mid = mid;
            e.Hi = hi;
            e.Face = face;
            side |= static_cast<uint8_t>(FaceParity(tp, face) ? 1u << (face & 3u) : 0u);
          });
        sides[t] = side;
      }
    });

  std::atomic<vtkIdType> nonManifold(0);
  // Two non-degenerate tetrahedra on one side of a face overlap (vtkTetMeshOverlapRule).
  const uint8_t* flags = mesh->TetFlags.data();
  const uint32_t* inputCells = mesh->TetInputCellIds.data();
  auto side = [sides](uint32_t f) { return ((sides[f >> 2] >> (f & 3u)) & 1u) != 0; };
  auto overlap = [side, flags](uint32_t a, uint32_t b)
  {
    return side(a) == side(b) && !(flags[a >> 2] & vtkTetMesh::Degenerate) &&
      !(flags[b >> 2] & vtkTetMesh::Degenerate);
  };
  std::vector<uint32_t> leftOut;
  std::mutex leftOutMutex;
  vtkSMPTools::For(0, static_cast<vtkIdType>(numPoints), 2048,
    [&](vtkIdType vb, vtkIdType ve)
    {
      vtkIdType localNonManifold = 0;
      std::vector<vtkTetMeshOverlapRule::Entry> rule;
      std::vector<uint32_t> localLeftOut;
      // A small open-addressing table per bucket: slot -> 1 + index of the first face seen
      // with that key, the top bit set once it is paired. Linear in the bucket's size, where a
      // sort is not, and buckets of meshes numbered at random hold dozens of faces.
      std::vector<uint32_t> table;
      constexpr uint32_t Paired = 0x80000000u;
      for (vtkIdType v = vb; v < ve; ++v)
      {
        FaceEntry* first = entries + start[v];
        FaceEntry* last = entries + start[v + 1];
        const ptrdiff_t n = last - first;
        if (n < 2)
        {
          continue;
        }
        size_t size = 8;
        while (size < 2 * static_cast<size_t>(n))
        {
          size <<= 1;
        }
        if (table.size() < size)
        {
          table.resize(size);
        }
        std::fill(table.begin(), table.begin() + size, 0u);
        const size_t mask = size - 1;
        bool thirdFace = false;
        for (ptrdiff_t k = 0; k < n && !thirdFace; ++k)
        {
          const FaceEntry& e = first[k];
          size_t h = ((e.Mid * 0x9e3779b1u) ^ (e.Hi * 0x85ebca77u)) & mask;
          for (;;)
          {
            const uint32_t slot = table[h];
            if (slot == 0)
            {
              table[h] = static_cast<uint32_t>(k + 1);
              break;
            }
            const FaceEntry& o = first[(slot & ~Paired) - 1];
            if (SameFace(o, e))
            {
              // A third tetrahedron, or two on one side (they overlap): the slow path below.
              if ((slot & Paired) || overlap(o.Face, e.Face))
              {
                thirdFace = true;
              }
              else
              {
                neighbors[o.Face] = e.Face;
                neighbors[e.Face] = o.Face;
                table[h] = slot | Paired;
              }
              break;
            }
            h = (h + 1) & mask;
          }
        }
        if (!thirdFace)
        {
          continue;
        }
        // A face shared by more than two tetrahedra or by two on one side (rare): start the
        // bucket over, sorted, and follow vtkTetMeshOverlapRule.
        for (FaceEntry* e = first; e < last; ++e)
        {
          neighbors[e->Face] = NoNeighbor;
        }
        std::sort(first, last, FaceEntryLess);
        for (FaceEntry* run = first; run < last;)
        {
          FaceEntry* runEnd = run + 1;
          while (runEnd < last && SameFace(*runEnd, *run))
          {
            ++runEnd;
          }
          const ptrdiff_t m = runEnd - run;
          if (m == 2 && !overlap(run[0].Face, run[1].Face))
          {
            neighbors[run[0].Face] = run[1].Face;
            neighbors[run[1].Face] = run[0].Face;
          }
          else if (m >= 2)
          {
            localNonManifold += m > 2 ? 1 : 0;
            rule.clear();
            for (FaceEntry* e = run; e < runEnd; ++e)
            {
              const uint32_t t = e->Face >> 2;
              rule.push_back({ e->Face, side(e->Face),
                (flags[t] & vtkTetMesh::Degenerate) != 0, inputCells[t] });
            }
            uint32_t link[2];
            vtkTetMeshOverlapRule::Resolve(rule.data(), rule.size(), link, localLeftOut);
            if (link[0] != NoNeighbor)
            {
              neighbors[link[0]] = link[1];
              neighbors[link[1]] = link[0];
            }
          }
          run = runEnd;
        }
      }
      nonManifold += localNonManifold;
      if (!localLeftOut.empty())
      {
        std::lock_guard<std::mutex> lock(leftOutMutex);
        leftOut.insert(leftOut.end(), localLeftOut.begin(), localLeftOut.end());
      }
    });
  this->NumberOfNonManifoldFaces = nonManifold;
  this->NumberOfOverlappingTetrahedra = vtkTetMeshOverlapRule::Apply(
    leftOut, neighbors, mesh->TetFlags.data(), static_cast<uint8_t>(vtkTetMesh::Overlapping));
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
void vtkTetMeshBuilder::vtkInternals::OrientDegenerateTetrahedra()
{
  vtkTetMesh* mesh = this->Mesh;
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
      if (FaceParity(tp, face) == FaceParity(tp, neighbors[face]))
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

//------------------------------------------------------------------------------
void vtkTetMeshBuilder::vtkInternals::CollectBoundaryFaces()
{
  vtkTetMesh* mesh = this->Mesh;
  const vtkIdType numFaces = 4 * mesh->GetNumberOfTetrahedra();
  const uint32_t* neighbors = mesh->TetNeighbors.data();
  const uint8_t* flags = mesh->TetFlags.data();
  // Faces of tetrahedra left out (vtkTetMeshOverlapRule) are no boundary: they are never entered.
  auto boundary = [neighbors, flags](vtkIdType f)
  { return neighbors[f] == NoNeighbor && !(flags[f >> 2] & vtkTetMesh::Overlapping); };
  const int blocks = NumberOfBlocks(numFaces);
  std::vector<size_t> counts(static_cast<size_t>(blocks) + 1, 0);
  ForBlocks(numFaces, blocks,
    [&](int b, vtkIdType begin, vtkIdType end)
    {
      size_t n = 0;
      for (vtkIdType f = begin; f < end; ++f)
      {
        n += boundary(f) ? 1 : 0;
      }
      counts[b + 1] = n;
    });
  std::partial_sum(counts.begin(), counts.end(), counts.begin());
  mesh->BoundaryFaces.resize(counts[blocks]);
  uint32_t* out = mesh->BoundaryFaces.data();
  ForBlocks(numFaces, blocks,
    [&](int b, vtkIdType begin, vtkIdType end)
    {
      size_t pos = counts[b];
      for (vtkIdType f = begin; f < end; ++f)
      {
        if (boundary(f))
        {
          out[pos++] = static_cast<uint32_t>(f);
        }
      }
    });
}

//------------------------------------------------------------------------------
// Duplicate points: a hash of the coordinates, bucketed. Crack faces: boundary faces
// that overlap another boundary face made of coincident but distinct points (same plane,
// facing the other way, interiors intersecting), as along an unwelded seam.
void vtkTetMeshBuilder::vtkInternals::FindDuplicatesAndCracks()
{
  vtkTetMesh* mesh = this->Mesh;
  const vtkIdType numPoints = mesh->GetNumberOfPoints();
  const double* p = mesh->Points.data();
  this->NumberOfDuplicatePoints = 0;
  this->NumberOfCrackFaces = 0;
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
  std::vector<uint32_t>& bucketOf = this->PointBuckets;
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
  std::vector<uint32_t>& bucketStart = this->PointBucketStarts;
  bucketStart.assign(numBuckets + 1, 0u);
  for (uint32_t b : bucketOf)
  {
    ++bucketStart[b + 1];
  }
  std::partial_sum(bucketStart.begin(), bucketStart.end(), bucketStart.begin());
  std::vector<uint32_t>& order = this->PointOrder;
  order.resize(static_cast<size_t>(numPoints));
  for (size_t i = 0; i < order.size(); ++i)
  {
    // bucketStart[b] runs ahead while filling bucket b - 1: shift back afterwards.
    order[bucketStart[bucketOf[i]]++] = static_cast<uint32_t>(i);
  }
  std::copy_backward(bucketStart.begin(), bucketStart.end() - 1, bucketStart.end());
  bucketStart[0] = 0;
  // canonical[v]: the smallest id with v's coordinates (only where v has duplicates).
  std::vector<uint32_t>& canonical = this->Canonical;
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
  this->NumberOfDuplicatePoints = duplicates;
  if (duplicates == 0)
  {
    return;
  }

  // Boundary faces touching a duplicated point, listed under that point's canonical id.
  const uint32_t* tp = mesh->TetPoints.data();
  const std::vector<uint32_t>& boundary = mesh->BoundaryFaces;
  auto facePoint = [&](uint32_t face, int k)
  { return tp[4 * static_cast<size_t>(face >> 2) + vtkTetMesh::FacePoints[face & 3u][k]]; };
  std::vector<std::pair<uint32_t, uint32_t>> links; // (canonical id, index into boundary)
  for (size_t b = 0; b < boundary.size(); ++b)
  {
    for (int k = 0; k < 3; ++k)
    {
      const uint32_t v = facePoint(boundary[b], k);
      if (canonical[v] != NoNeighbor)
      {
        links.emplace_back(canonical[v], static_cast<uint32_t>(b));
      }
    }
  }
  if (links.empty())
  {
    return;
  }
  std::sort(links.begin(), links.end());
  links.erase(std::unique(links.begin(), links.end()), links.end());

  auto overlaps = [&](uint32_t f, uint32_t g)
  {
    double a[3][3], b[3][3];
    for (int k = 0; k < 3; ++k)
    {
      std::copy(p + 3 * static_cast<size_t>(facePoint(f, k)),
        p + 3 * static_cast<size_t>(facePoint(f, k)) + 3, a[k]);
      std::copy(p + 3 * static_cast<size_t>(facePoint(g, k)),
        p + 3 * static_cast<size_t>(facePoint(g, k)) + 3, b[k]);
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
    // Overlapping interiors, in the plane of f.
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
  };

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
        const uint32_t ids[3] = { facePoint(f, 0), facePoint(f, 1), facePoint(f, 2) };
        candidates.clear();
        for (int k = 0; k < 3; ++k)
        {
          const uint32_t v = ids[k];
          if (canonical[v] == NoNeighbor)
          {
            continue;
          }
          auto range =
            std::equal_range(links.begin(), links.end(), std::make_pair(canonical[v], uint32_t(0)),
              [](const std::pair<uint32_t, uint32_t>& x, const std::pair<uint32_t, uint32_t>& y)
              { return x.first < y.first; });
          for (auto it = range.first; it != range.second; ++it)
          {
            const uint32_t g = boundary[it->second];
            // Only faces that reach this location through another point id: coincident but
            // not shared.
            bool usesV = false;
            for (int m = 0; m < 3; ++m)
            {
              usesV = usesV || facePoint(g, m) == v;
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
          if (overlaps(f, g))
          {
            ++found;
            break;
          }
        }
      }
      cracks += found;
    });
  this->NumberOfCrackFaces = cracks;
}

//------------------------------------------------------------------------------
bool vtkTetMeshBuilder::vtkInternals::ReadScalars(
  vtkDataSet* input, vtkTetMeshBuilder* self, std::string& error)
{
  vtkTetMesh* mesh = this->Mesh;
  mesh->PointScalars.clear();
  mesh->CellScalars.clear();
  this->InputCellScalars.clear();
  mesh->HasCellScalars = false;
  mesh->ScalarRange[0] = mesh->ScalarRange[1] = 0.0;
  this->NumberOfNonFiniteScalars = 0;
  this->ScalarsStamp = Stamp();
  this->ScalarsCellFlag = -1;

  int cellFlag = -1;
  vtkDataArray* array = vtkAbstractMapper::GetScalars(
    input, self->ScalarMode, self->ArrayAccessMode, self->ArrayId, self->ArrayName, cellFlag);
  std::ostringstream text;
  if (!array)
  {
    text << "no scalars to render: ";
    if (self->ScalarMode == VTK_SCALAR_MODE_USE_POINT_FIELD_DATA ||
      self->ScalarMode == VTK_SCALAR_MODE_USE_CELL_FIELD_DATA ||
      self->ScalarMode == VTK_SCALAR_MODE_USE_FIELD_DATA)
    {
      const bool byName = self->ArrayAccessMode == VTK_GET_ARRAY_BY_NAME;
      text << "the "
           << (self->ScalarMode == VTK_SCALAR_MODE_USE_POINT_FIELD_DATA ? "point" : "cell")
           << " data has no numeric array ";
      if (byName)
      {
        text << "named \"" << (self->ArrayName ? self->ArrayName : "") << "\"";
      }
      else
      {
        text << "with index " << self->ArrayId;
      }
    }
    else
    {
      text << "the grid has no active "
           << (self->ScalarMode == VTK_SCALAR_MODE_USE_POINT_DATA     ? "point "
                  : self->ScalarMode == VTK_SCALAR_MODE_USE_CELL_DATA ? "cell "
                                                                      : "point or cell ")
           << "scalars";
    }
    error = text.str();
    return false;
  }
  if (cellFlag != 0 && cellFlag != 1)
  {
    error = "field-data scalars are not supported: select point or cell data";
    return false;
  }
  const vtkIdType expected = cellFlag == 0 ? input->GetNumberOfPoints() : input->GetNumberOfCells();
  const int numComponents = array->GetNumberOfComponents();
  const bool magnitude = self->VectorMode == Magnitude && numComponents > 1;
  const int component = numComponents > 1 ? self->VectorComponent : 0;
  if (array->GetNumberOfTuples() != expected)
  {
    text << "the scalar array \"" << (array->GetName() ? array->GetName() : "") << "\" has "
         << array->GetNumberOfTuples() << " values for " << expected
         << (cellFlag == 0 ? " points" : " cells");
    error = text.str();
    return false;
  }
  if (!magnitude && component >= numComponents)
  {
    text << "component " << component << " was selected from the scalar array \""
         << (array->GetName() ? array->GetName() : "") << "\", which has only " << numComponents;
    error = text.str();
    return false;
  }

  std::vector<double>& values = cellFlag == 0 ? mesh->PointScalars : this->InputCellScalars;
  values.resize(static_cast<size_t>(expected));
  vtkTetScalarSelection::Extract(array, magnitude, component, values.data());

  double range[2] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  vtkIdType nonFinite = 0;
  for (double v : values)
  {
    if (std::isfinite(v))
    {
      range[0] = std::min(range[0], v);
      range[1] = std::max(range[1], v);
    }
    else
    {
      ++nonFinite;
    }
  }
  if (range[0] > range[1])
  {
    range[0] = range[1] = 0.0;
  }
  mesh->ScalarRange[0] = range[0];
  mesh->ScalarRange[1] = range[1];
  this->NumberOfNonFiniteScalars = nonFinite;
  mesh->HasCellScalars = cellFlag == 1;
  this->ScalarsStamp = MakeStamp(array);
  this->ScalarsCellFlag = cellFlag;
  if (mesh->HasCellScalars)
  {
    const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
    mesh->CellScalars.resize(static_cast<size_t>(numTets));
    for (vtkIdType t = 0; t < numTets; ++t)
    {
      mesh->CellScalars[t] = this->InputCellScalars[mesh->TetInputCellIds[t]];
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTetMeshBuilder::vtkInternals::FlagNonFiniteTets()
{
  vtkTetMesh* mesh = this->Mesh;
  const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
  uint8_t* flags = mesh->TetFlags.data();
  const uint32_t* tp = mesh->TetPoints.data();
  const bool cell = mesh->HasCellScalars;
  const double* s = cell ? mesh->CellScalars.data() : mesh->PointScalars.data();
  const bool any = mesh->HasScalars() && this->NumberOfNonFiniteScalars > 0;
  vtkSMPTools::For(0, numTets, 16384,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType t = begin; t < end; ++t)
      {
        bool bad = false;
        if (any)
        {
          bad = cell ? !std::isfinite(s[t])
                     : !(std::isfinite(s[tp[4 * t]]) && std::isfinite(s[tp[4 * t + 1]]) &&
                         std::isfinite(s[tp[4 * t + 2]]) && std::isfinite(s[tp[4 * t + 3]]));
        }
        flags[t] = bad ? (flags[t] | vtkTetMesh::NonFiniteScalars)
                       : (flags[t] & static_cast<uint8_t>(~vtkTetMesh::NonFiniteScalars));
      }
    });
}

//------------------------------------------------------------------------------
vtkTetMeshBuilder::vtkTetMeshBuilder()
  : ScalarMode(VTK_SCALAR_MODE_DEFAULT)
  , ArrayAccessMode(VTK_GET_ARRAY_BY_ID)
  , Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkTetMeshBuilder::~vtkTetMeshBuilder()
{
  this->SetArrayName(nullptr);
}

//------------------------------------------------------------------------------
void vtkTetMeshBuilder::SelectScalarArray(int arrayId)
{
  if (this->ArrayAccessMode == VTK_GET_ARRAY_BY_ID && this->ArrayId == arrayId)
  {
    return;
  }
  this->ArrayId = arrayId;
  this->ArrayAccessMode = VTK_GET_ARRAY_BY_ID;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkTetMeshBuilder::SelectScalarArray(const char* arrayName)
{
  if (!arrayName ||
    (this->ArrayAccessMode == VTK_GET_ARRAY_BY_NAME && this->ArrayName &&
      std::strcmp(this->ArrayName, arrayName) == 0))
  {
    return;
  }
  this->SetArrayName(arrayName);
  this->ArrayAccessMode = VTK_GET_ARRAY_BY_NAME;
  this->Modified();
}

//------------------------------------------------------------------------------
vtkTetMesh* vtkTetMeshBuilder::GetMesh()
{
  return this->Internals->Mesh;
}

//------------------------------------------------------------------------------
void vtkTetMeshBuilder::Invalidate()
{
  this->Internals->Valid = false;
}

//------------------------------------------------------------------------------
void vtkTetMeshBuilder::ReleaseScratchMemory()
{
  this->Internals->ReleaseScratch();
}

//------------------------------------------------------------------------------
vtkIdType vtkTetMeshBuilder::GetScratchMemorySize()
{
  return this->Internals->ScratchSize();
}

//------------------------------------------------------------------------------
const char* vtkTetMeshBuilder::GetRebuildAsString(int rebuild)
{
  switch (rebuild & RebuildAll)
  {
    case RebuildNothing:
      return "nothing";
    case RebuildScalars:
      return "scalars";
    case RebuildPoints:
      return "points";
    case RebuildPoints | RebuildScalars:
      return "points and scalars";
    default:
      return "all";
  }
}

//------------------------------------------------------------------------------
vtkTetMesh* vtkTetMeshBuilder::Build(vtkDataSet* input)
{
  const double start = vtkTimerLog::GetUniversalTime();
  vtkInternals& in = *this->Internals;
  vtkTetMesh* mesh = in.Mesh;
  this->LastRebuild = RebuildNothing;

  // What changed since the last build?
  std::vector<Stamp> topology;
  in.GetTopologyStamps(input, topology);
  const Stamp pointsStamp = vtkInternals::GetPointsStamp(input);
  const std::string arrayName = this->ArrayName ? this->ArrayName : "";
  int cellFlag = -1;
  vtkDataArray* scalars = input ? vtkAbstractMapper::GetScalars(input, this->ScalarMode,
                                    this->ArrayAccessMode, this->ArrayId, this->ArrayName, cellFlag)
                                : nullptr;
  const bool full = !in.Valid || in.Input != input || in.TopologyStamps != topology ||
    in.NumberOfPoints != (input ? input->GetNumberOfPoints() : -1) ||
    in.SpatialOrdering != this->SpatialOrdering ||
    in.DegeneracyTolerance != this->DegeneracyTolerance;
  bool pointsChanged = full || in.PointsStamp != pointsStamp;
  bool scalarsChanged = full || in.ScalarsStamp != MakeStamp(scalars) ||
    in.ScalarsCellFlag != (scalars ? cellFlag : -1) || in.ScalarMode != this->ScalarMode ||
    in.ArrayAccessMode != this->ArrayAccessMode || in.ArrayId != this->ArrayId ||
    in.ArrayName != arrayName || in.VectorMode != this->VectorMode ||
    in.VectorComponent != this->VectorComponent;
  if (!pointsChanged && !scalarsChanged)
  {
    this->LastBuildTime = vtkTimerLog::GetUniversalTime() - start;
    return mesh;
  }

  ReportProgress(this, 0.0);
  bool doFull = full;
  if (!doFull && pointsChanged)
  {
    // Deforming mesh: new positions, same tetrahedra.
    std::string error;
    ScopedEvent event("vtkTetMeshBuilder: points only");
    if (!in.ReadPoints(input, error))
    {
      in.TopologyError = error;
      mesh->Initialize();
      this->LastRebuild = RebuildAll;
      vtkErrorMacro(<< "Cannot build a tetrahedral mesh: " << error << ".");
    }
    else if (!in.TopologyError.empty() || !in.OrientAndClassify(this->DegeneracyTolerance, false))
    {
      // A tetrahedron turned inside out (or the last build had failed): start over.
      doFull = true;
    }
    else
    {
      this->LastRebuild |= RebuildPoints;
      mesh->PointsTime.Modified();
    }
    in.PointsStamp = pointsStamp;
  }

  if (doFull)
  {
    this->LastRebuild = RebuildAll;
    in.Valid = false;
    in.NumberOfInputCells = input ? input->GetNumberOfCells() : 0;
    in.NumberOfSplitCells = in.NumberOfIgnoredCells = in.NumberOfInvalidCells = 0;
    in.NumberOfInvertedTetrahedra = in.NumberOfDegenerateTetrahedra = 0;
    in.NumberOfNonManifoldFaces = in.NumberOfCrackFaces = in.NumberOfDuplicatePoints = 0;
    in.NumberOfOverlappingTetrahedra = 0;
    in.NumberOfNonFiniteScalars = 0;
    in.DegenerateCellIds.clear();
    in.TopologyError.clear();
    in.ScalarError.clear();
    mesh->Initialize();

    std::string error;
    vtkIdType numTetsFromSplit = 0;
    if (!input)
    {
      error = "no input";
    }
    else if (input->GetNumberOfPoints() == 0 || input->GetNumberOfCells() == 0)
    {
      error = "the grid is empty";
    }
    else if (input->GetNumberOfPoints() >= static_cast<vtkIdType>(NoNeighbor) ||
      input->GetNumberOfCells() >= static_cast<vtkIdType>(NoNeighbor))
    {
      error = "the grid has too many points or cells (at most 2^32 - 1 of each)";
    }
    else
    {
      bool ok;
      {
        ScopedEvent event("vtkTetMeshBuilder: points");
        ok = in.ReadPoints(input, error);
      }
      if (ok)
      {
        ScopedEvent event("vtkTetMeshBuilder: cells");
        ok = in.ExtractTetrahedra(input, error, numTetsFromSplit);
      }
      ReportProgress(this, 0.1);
      const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
      if (ok && numTets == 0)
      {
        std::ostringstream text;
        text << "the grid has no 3D cells (" << in.NumberOfIgnoredCells
             << " cells of lower dimension";
        if (in.NumberOfInvalidCells > 0)
        {
          text << ", " << in.NumberOfInvalidCells << " invalid cells";
        }
        text << ")";
        error = text.str();
      }
      else if (ok && numTets > MaxTetrahedra)
      {
        std::ostringstream text;
        text << "the grid gives " << numTets << " tetrahedra, more than the 2^30 a mesh can hold";
        error = text.str();
      }
    }
    if (!error.empty())
    {
      in.TopologyError = error;
      mesh->TetPoints.clear();
      mesh->TetInputCellIds.clear();
      vtkErrorMacro(<< "Cannot build a tetrahedral mesh: " << error << ".");
    }
    else
    {
      // Splitting non-tetrahedral cells (and reorienting inverted tetrahedra) is normal service:
      // the report counts them, and only what the builder could not use is warned about.
      if (in.NumberOfIgnoredCells > 0 || in.NumberOfInvalidCells > 0)
      {
        vtkWarningMacro(<< "Ignored " << in.NumberOfIgnoredCells
                        << " cells of dimension lower than 3 (or of unsupported types) and "
                        << in.NumberOfInvalidCells << " invalid cells (bad point ids).");
      }
      // Each phase is a vtkTimerLog event (recorded when vtkTimerLog::LoggingOn()): the
      // benchmark prints them, face matching being the part that grows fastest.
      if (this->SpatialOrdering)
      {
        ScopedEvent event("vtkTetMeshBuilder: spatial sort");
        in.SortSpatially();
      }
      {
        ScopedEvent event("vtkTetMeshBuilder: orientation");
        in.OrientAndClassify(this->DegeneracyTolerance, true);
      }
      ReportProgress(this, 0.3);
      {
        ScopedEvent event("vtkTetMeshBuilder: face matching");
        in.MatchFaces();
        in.OrientDegenerateTetrahedra();
        in.CollectBoundaryFaces();
      }
      ReportProgress(this, 0.85);
      {
        ScopedEvent event("vtkTetMeshBuilder: duplicates and cracks");
        in.FindDuplicatesAndCracks();
      }
      ReportProgress(this, 0.95);
    }
    in.Input = input;
    in.TopologyStamps = topology;
    in.PointsStamp = pointsStamp;
    in.NumberOfPoints = input ? input->GetNumberOfPoints() : -1;
    in.SpatialOrdering = this->SpatialOrdering;
    in.DegeneracyTolerance = this->DegeneracyTolerance;
    in.Valid = true;
    mesh->TopologyTime.Modified();
    mesh->PointsTime.Modified();
    scalarsChanged = true;
  }

  if (scalarsChanged)
  {
    in.ScalarError.clear();
    if (in.TopologyError.empty())
    {
      ScopedEvent event("vtkTetMeshBuilder: scalars");
      std::string error;
      if (!in.ReadScalars(input, this, error))
      {
        in.ScalarError = error;
        vtkErrorMacro(<< "Cannot render the grid: " << error << ".");
      }
      in.FlagNonFiniteTets();
    }
    in.ScalarMode = this->ScalarMode;
    in.ArrayAccessMode = this->ArrayAccessMode;
    in.ArrayId = this->ArrayId;
    in.ArrayName = arrayName;
    in.VectorMode = this->VectorMode;
    in.VectorComponent = this->VectorComponent;
    // ReadScalars records the array it used; keep the one the change test sees otherwise.
    if (!in.TopologyError.empty() || !in.ScalarError.empty())
    {
      in.ScalarsStamp = MakeStamp(scalars);
      in.ScalarsCellFlag = scalars ? cellFlag : -1;
    }
    this->LastRebuild |= RebuildScalars;
    mesh->ScalarsTime.Modified();
  }

  in.ReportTo(mesh->Report, input);
  mesh->Modified();
  this->LastBuildTime = vtkTimerLog::GetUniversalTime() - start;
  ReportProgress(this, 1.0);
  return mesh;
}

//------------------------------------------------------------------------------
void vtkTetMeshBuilder::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ScalarMode: " << this->ScalarMode << "\n";
  os << indent << "ArrayAccessMode: " << this->ArrayAccessMode << "\n";
  os << indent << "ArrayId: " << this->ArrayId << "\n";
  os << indent << "ArrayName: " << (this->ArrayName ? this->ArrayName : "(none)") << "\n";
  os << indent << "VectorMode: " << (this->VectorMode == Magnitude ? "Magnitude" : "Component")
     << "\n";
  os << indent << "VectorComponent: " << this->VectorComponent << "\n";
  os << indent << "SpatialOrdering: " << (this->SpatialOrdering ? "On" : "Off") << "\n";
  os << indent << "DegeneracyTolerance: " << this->DegeneracyTolerance << "\n";
  os << indent << "LastRebuild: " << GetRebuildAsString(this->LastRebuild) << "\n";
  os << indent << "LastBuildTime: " << this->LastBuildTime << "\n";
  os << indent << "Mesh: " << this->Internals->Mesh.GetPointer() << "\n";
}
