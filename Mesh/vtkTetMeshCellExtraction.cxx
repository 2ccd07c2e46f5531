/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshCellExtraction.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetMeshCellExtraction.h"

#include "vtkArrayDispatch.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArrayRange.h"
#include "vtkDataSet.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"
#include "vtkTetMesh.h"
#include "vtkTetMeshBuildState.h"
#include "vtkTetMeshValidationReport.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <sstream>
#include <vector>

namespace
{
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
}

//------------------------------------------------------------------------------
// The cell-by-cell path: tetrahedra go straight into the mesh, cells to split are gathered
// into a grid that shares the mesh's points, bad and lower-dimensional cells are counted.
class vtkTetMeshCellExtraction::vtkCellCollector
{
public:
  vtkCellCollector(vtkTetMeshBuildState& state, vtkIdType numPoints)
    : Mesh(state.Mesh)
    , NumberOfPoints(numPoints)
  {
    this->ToSplitIds->SetName("vtkTetMeshBuilderCellIds");
    this->ToSplit->Allocate(64);
  }

  bool ValidIds(const vtkIdType* ids, vtkIdType n) const
  {
    for (vtkIdType k = 0; k < n; ++k)
    {
      if (ids[k] < 0 || ids[k] >= this->NumberOfPoints)
      {
        return false;
      }
    }
    return true;
  }

  void AddTet(const vtkIdType* ids, vtkIdType cellId)
  {
    for (int k = 0; k < 4; ++k)
    {
      this->Mesh->TetPoints.push_back(static_cast<uint32_t>(ids[k]));
    }
    this->Mesh->TetInputCellIds.push_back(static_cast<uint32_t>(cellId));
  }

  void AddToSplit(int type, vtkIdList* ids, vtkIdType cellId)
  {
    this->ToSplit->InsertNextCell(type, ids);
    this->ToSplitIds->InsertNextValue(cellId);
  }

  vtkTetMesh* Mesh;
  vtkIdType NumberOfPoints;
  vtkNew<vtkUnstructuredGrid> ToSplit;
  vtkNew<vtkIdTypeArray> ToSplitIds;
  vtkNew<vtkIdList> PointIds;
  vtkIdType NumberOfIgnoredCells = 0;
  vtkIdType NumberOfInvalidCells = 0;
};

//------------------------------------------------------------------------------
bool vtkTetMeshCellExtraction::ReadPoints(
  vtkTetMeshBuildState& state, vtkDataSet* input, std::string& error)
{
  vtkTetMesh* mesh = state.Mesh;
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
  // drawn from them, and they would break the later stages' sorts.
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
  ComputeBounds(state);
  return true;
}

//------------------------------------------------------------------------------
void vtkTetMeshCellExtraction::ComputeBounds(vtkTetMeshBuildState& state)
{
  vtkTetMesh* mesh = state.Mesh;
  const vtkIdType n = mesh->GetNumberOfPoints();
  const double* p = mesh->Points.data();
  const int blocks = vtkTetMeshBuildState::NumberOfBlocks(n);
  std::vector<double> partial(6 * static_cast<size_t>(blocks));
  vtkTetMeshBuildState::ForBlocks(n, blocks,
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
bool vtkTetMeshCellExtraction::ExtractTetrahedra(
  vtkTetMeshBuildState& state, vtkDataSet* input, std::string& error)
{
  vtkTetMesh* mesh = state.Mesh;
  mesh->TetPoints.clear();
  mesh->TetInputCellIds.clear();

  auto* ug = vtkUnstructuredGrid::SafeDownCast(input);
  vtkCellArray* cells = ug ? ug->GetCells() : nullptr;
  vtkUnsignedCharArray* types = ug ? ug->GetCellTypesArray() : nullptr;
  const bool readGrid =
    ug && cells && types && types->GetNumberOfValues() >= input->GetNumberOfCells();
  if (readGrid && CopyAllTetrahedra(state, ug))
  {
    return true;
  }

  vtkCellCollector collector(state, input->GetNumberOfPoints());
  if (readGrid)
  {
    CollectGridCells(collector, ug);
  }
  else
  {
    CollectDataSetCells(collector, input);
  }
  vtkTetMeshValidationReport* report = state.GetReport();
  report->SetNumberOfIgnoredCells(collector.NumberOfIgnoredCells);
  report->SetNumberOfInvalidCells(collector.NumberOfInvalidCells);
  report->SetNumberOfSplitCells(collector.ToSplit->GetNumberOfCells());
  return SplitCells(collector, error);
}

//------------------------------------------------------------------------------
// The common case, all linear tetrahedra: a parallel copy of the connectivity. False (and
// nothing listed) when the grid holds any other cell, bad point ids or irregular offsets: the
// cell-by-cell path then takes over, and drops the bad cells.
bool vtkTetMeshCellExtraction::CopyAllTetrahedra(
  vtkTetMeshBuildState& state, vtkUnstructuredGrid* ug)
{
  vtkTetMesh* mesh = state.Mesh;
  const vtkIdType numPoints = ug->GetNumberOfPoints();
  const vtkIdType numCells = ug->GetNumberOfCells();
  vtkCellArray* cells = ug->GetCells();
  const unsigned char* typePtr = ug->GetCellTypesArray()->GetPointer(0);
  std::atomic<bool> allTets(cells->GetNumberOfConnectivityIds() == 4 * numCells);
  vtkSMPTools::For(0, allTets ? numCells : 0, 1 << 20,
    [&](vtkIdType begin, vtkIdType end)
    {
      if (allTets &&
        std::any_of(
          typePtr + begin, typePtr + end, [](unsigned char type) { return type != VTK_TETRA; }))
      {
        allTets = false;
      }
    });
  if (!allTets)
  {
    return false;
  }
  vtkTetMeshWords& tetPoints = mesh->TetPoints;
  vtkTetMeshVector<uint32_t>& cellIds = mesh->TetInputCellIds;
  tetPoints.resize(4 * static_cast<size_t>(numCells));
  cellIds.resize(static_cast<size_t>(numCells));
  std::atomic<vtkIdType> invalid(0);
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
    copy(cells->GetConnectivityArray64()->GetPointer(0), cells->GetOffsetsArray64()->GetPointer(0));
  }
  else
  {
    copy(cells->GetConnectivityArray32()->GetPointer(0), cells->GetOffsetsArray32()->GetPointer(0));
  }
  if (invalid == 0)
  {
    return true;
  }
  // Rare: the cell-by-cell path drops the bad cells.
  tetPoints.clear();
  cellIds.clear();
  return false;
}

//------------------------------------------------------------------------------
void vtkTetMeshCellExtraction::CollectGridCells(
  vtkCellCollector& collector, vtkUnstructuredGrid* ug)
{
  const vtkIdType numCells = ug->GetNumberOfCells();
  vtkCellArray* cells = ug->GetCells();
  const unsigned char* typePtr = ug->GetCellTypesArray()->GetPointer(0);
  vtkIdList* ptIds = collector.PointIds;
  collector.Mesh->TetPoints.reserve(4 * static_cast<size_t>(numCells));
  collector.Mesh->TetInputCellIds.reserve(static_cast<size_t>(numCells));
  vtkIdType npts;
  const vtkIdType* pts;
  for (vtkIdType c = 0; c < numCells; ++c)
  {
    const int type = typePtr[c];
    const CellKind kind = ClassifyCellType(type);
    if (kind == CellKind::LowerDim || kind == CellKind::Unsupported)
    {
      ++collector.NumberOfIgnoredCells;
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
          collector.ValidIds(ptIds->GetPointer(pos + 1), nf);
        pos += 1 + nf;
      }
      if (!ok)
      {
        ++collector.NumberOfInvalidCells;
        continue;
      }
      collector.AddToSplit(type, ptIds, c);
      continue;
    }
    cells->GetCellAtId(c, npts, pts);
    if (!collector.ValidIds(pts, npts) || (kind == CellKind::Tetra && npts != 4))
    {
      ++collector.NumberOfInvalidCells;
      continue;
    }
    if (kind == CellKind::Tetra)
    {
      collector.AddTet(pts, c);
    }
    else
    {
      ptIds->SetNumberOfIds(npts);
      std::copy(pts, pts + npts, ptIds->GetPointer(0));
      collector.AddToSplit(type, ptIds, c);
    }
  }
}

//------------------------------------------------------------------------------
// Any other data set, one cell at a time.
void vtkTetMeshCellExtraction::CollectDataSetCells(vtkCellCollector& collector, vtkDataSet* input)
{
  const vtkIdType numCells = input->GetNumberOfCells();
  vtkIdList* ptIds = collector.PointIds;
  for (vtkIdType c = 0; c < numCells; ++c)
  {
    const int type = input->GetCellType(c);
    const CellKind kind = ClassifyCellType(type);
    if (kind == CellKind::LowerDim || kind == CellKind::Unsupported ||
      type == VTK_POLYHEDRON) // needs a face stream, which only vtkUnstructuredGrid gives
    {
      ++collector.NumberOfIgnoredCells;
      continue;
    }
    input->GetCellPoints(c, ptIds);
    const vtkIdType npts = ptIds->GetNumberOfIds();
    if (!collector.ValidIds(ptIds->GetPointer(0), npts) || (kind == CellKind::Tetra && npts != 4))
    {
      ++collector.NumberOfInvalidCells;
      continue;
    }
    if (kind == CellKind::Tetra)
    {
      collector.AddTet(ptIds->GetPointer(0), c);
    }
    else
    {
      collector.AddToSplit(type, ptIds, c);
    }
  }
}

//------------------------------------------------------------------------------
// The gathered non-tetrahedral cells through vtkDataSetTriangleFilter, whose tetrahedra are
// appended with the input cell each came from.
bool vtkTetMeshCellExtraction::SplitCells(vtkCellCollector& collector, std::string& error)
{
  vtkTetMesh* mesh = collector.Mesh;
  vtkUnstructuredGrid* toSplit = collector.ToSplit;
  if (toSplit->GetNumberOfCells() == 0)
  {
    return true;
  }
  // The points are ours (double precision, same ids), wrapped without a copy.
  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetArray(mesh->Points.data(), static_cast<vtkIdType>(mesh->Points.size()), 1);
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  toSplit->SetPoints(points);
  toSplit->GetCellData()->AddArray(collector.ToSplitIds);

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
    if (tets->GetCellType(c) == VTK_TETRA && npts == 4 && collector.ValidIds(pts, 4))
    {
      collector.AddTet(pts, origin->GetValue(c));
    }
  }
  return true;
}
