/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetReferenceMesh.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetReferenceMesh.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkDoubleArray.h"
#include "vtkGenericCell.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkTetReferenceOverlaps.h"
#include "vtkTetScalarSelection.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace
{
const char* const CarriedScalarsName = "vtkTetReferenceRenderer_Scalars";

// Whether the input can be used as it is: an unstructured grid whose 3D cells are all
// tetrahedra (lower-dimensional cells are ignored).
bool AllTetrahedra(vtkDataSet* input)
{
  vtkUnstructuredGrid* grid = vtkUnstructuredGrid::SafeDownCast(input);
  if (!grid)
  {
    return false;
  }
  int dimension[256];
  std::fill(dimension, dimension + 256, -1);
  vtkNew<vtkGenericCell> cell;
  const vtkIdType numCells = grid->GetNumberOfCells();
  for (vtkIdType i = 0; i < numCells; ++i)
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
    if (dimension[type] >= 3)
    {
      return false;
    }
  }
  return true;
}
}

//------------------------------------------------------------------------------
// What the preparation holds between its steps.
class vtkTetReferenceMesh::vtkStaging
{
public:
  bool CellScalars = false;
  vtkNew<vtkDoubleArray> Reduced; // the selected scalars, one value each
  vtkDataSet* Mesh = nullptr;     // the input, or its split into tetrahedra
  vtkSmartPointer<vtkUnstructuredGrid> Triangulated;
  vtkDataArray* Scalars = nullptr; // Reduced, or what of it the split carried along
  vtkIdType NumberOfPoints = 0;
  std::vector<vtkIdType> RawTets;
  std::vector<vtkIdType> TetCell; // the cell (of Mesh) each tetrahedron comes from
  std::vector<double> World;
  double Diagonal = 0.0;
  // The tetrahedra kept, positively oriented, their cells and boxes.
  std::vector<vtkIdType> Tets;
  std::vector<vtkIdType> KeptCell;
  std::vector<double> Boxes;
};

//------------------------------------------------------------------------------
bool vtkTetReferenceMesh::IsPreparedFrom(
  vtkDataSet* input, vtkTetScalarSelection* selection, const double matrix[16]) const
{
  return this->Valid && this->Input == input && this->InputMTime == input->GetMTime() &&
    this->Selection->HasSameSettings(selection) && std::equal(matrix, matrix + 16, this->Matrix);
}

//------------------------------------------------------------------------------
bool vtkTetReferenceMesh::Prepare(vtkDataSet* input, vtkTetScalarSelection* selection,
  const double matrix[16], vtkIdType& degenerate, std::string& error)
{
  this->Valid = false;
  degenerate = 0;

  // Scalars, reduced to one component.
  int cellFlag = -1;
  vtkDataArray* array = selection->GetScalars(input, cellFlag);
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
  vtkStaging staging;
  staging.CellScalars = cellFlag == 1;
  staging.Reduced->SetName(CarriedScalarsName);
  staging.Reduced->SetNumberOfTuples(array->GetNumberOfTuples());
  vtkTetScalarSelection::Extract(array,
    selection->GetVectorMode() == vtkTetScalarSelection::MAGNITUDE, selection->GetVectorComponent(),
    staging.Reduced->GetPointer(0));

  if (!this->CollectTetrahedra(staging, input, error) ||
    !this->TransformPoints(staging, matrix, error))
  {
    return false;
  }
  this->OrientTetrahedra(staging, degenerate);
  this->LeaveOutOverlapping(staging);
  const size_t numTets = staging.KeptCell.size();
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
  this->StoreInHierarchyOrder(staging);

  this->Input = input;
  this->InputMTime = input->GetMTime();
  this->Selection = vtkSmartPointer<vtkTetScalarSelection>::New();
  this->Selection->CopySettings(selection);
  std::copy(matrix, matrix + 16, this->Matrix);
  this->Valid = true;
  return true;
}

//------------------------------------------------------------------------------
// Tetrahedra: used as they are when the input is an unstructured grid whose 3D cells are all
// tetrahedra; otherwise split by VTK.
bool vtkTetReferenceMesh::CollectTetrahedra(
  vtkStaging& staging, vtkDataSet* input, std::string& error)
{
  staging.Mesh = input;
  staging.Scalars = staging.Reduced;
  if (!AllTetrahedra(input))
  {
    // The reduced scalars ride along as an array of their own, so that point and cell
    // correspondences are the filter's business.
    vtkSmartPointer<vtkDataSet> copy = vtkSmartPointer<vtkDataSet>::Take(input->NewInstance());
    copy->ShallowCopy(input);
    if (staging.CellScalars)
    {
      copy->GetCellData()->AddArray(staging.Reduced);
    }
    else
    {
      copy->GetPointData()->AddArray(staging.Reduced);
    }
    vtkNew<vtkDataSetTriangleFilter> split;
    split->SetInputData(copy);
    split->TetrahedraOnlyOn();
    split->Update();
    staging.Triangulated = split->GetOutput();
    staging.Mesh = staging.Triangulated;
    staging.Scalars = staging.CellScalars
      ? staging.Triangulated->GetCellData()->GetArray(CarriedScalarsName)
      : staging.Triangulated->GetPointData()->GetArray(CarriedScalarsName);
    if (!staging.Scalars)
    {
      error = "Splitting the cells into tetrahedra lost the scalars.";
      return false;
    }
  }
  if (vtkUnstructuredGrid* ug = vtkUnstructuredGrid::SafeDownCast(staging.Mesh))
  {
    const vtkIdType numCells = ug->GetNumberOfCells();
    staging.RawTets.reserve(4 * static_cast<size_t>(numCells));
    for (vtkIdType i = 0; i < numCells; ++i)
    {
      if (ug->GetCellType(i) != VTK_TETRA)
      {
        continue;
      }
      vtkIdType npts;
      const vtkIdType* pts;
      ug->GetCellPoints(i, npts, pts);
      staging.RawTets.insert(staging.RawTets.end(), pts, pts + 4);
      staging.TetCell.push_back(i);
    }
  }
  staging.NumberOfPoints = staging.Mesh->GetNumberOfPoints();
  if (staging.TetCell.empty() || staging.NumberOfPoints < 4)
  {
    error = "The input has no tetrahedra (no 3D cells).";
    return false;
  }
  if (staging.Scalars->GetNumberOfTuples() !=
    (staging.CellScalars ? staging.Mesh->GetNumberOfCells() : staging.NumberOfPoints))
  {
    error = "The scalars do not match the mesh.";
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
// World coordinates, shifted to the centre of their bounds (precision far from the origin).
bool vtkTetReferenceMesh::TransformPoints(
  vtkStaging& staging, const double matrix[16], std::string& error)
{
  const vtkIdType numPoints = staging.NumberOfPoints;
  std::vector<double>& world = staging.World;
  world.resize(3 * static_cast<size_t>(numPoints));
  double bounds[6];
  vtkTetReferenceBVH::EmptyBox(bounds);
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    double p[3];
    staging.Mesh->GetPoint(i, p);
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
      vtkTetReferenceBVH::GrowBox(bounds, b);
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
  staging.Diagonal = std::sqrt((bounds[3] - bounds[0]) * (bounds[3] - bounds[0]) +
    (bounds[4] - bounds[1]) * (bounds[4] - bounds[1]) +
    (bounds[5] - bounds[2]) * (bounds[5] - bounds[2]));
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      world[3 * i + k] -= this->Center[k];
    }
  }
  return true;
}

//------------------------------------------------------------------------------
// Positive orientation (docs/design.md); zero-volume tetrahedra hold nothing and are dropped.
namespace
{
const double FlatTolerance = 1e-12;
}

void vtkTetReferenceMesh::OrientTetrahedra(vtkStaging& staging, vtkIdType& degenerate)
{
  const vtkIdType numPoints = staging.NumberOfPoints;
  const size_t numRaw = staging.TetCell.size();
  staging.Tets.reserve(4 * numRaw);
  staging.KeptCell.reserve(numRaw);
  staging.Boxes.reserve(6 * numRaw);
  for (size_t t = 0; t < numRaw; ++t)
  {
    const vtkIdType* raw = &staging.RawTets[4 * t];
    vtkIdType ids[4] = { raw[0], raw[1], raw[2], raw[3] };
    const double* p[4];
    bool finite = true;
    for (int k = 0; k < 4; ++k)
    {
      if (ids[k] < 0 || ids[k] >= numPoints)
      {
        finite = false;
        break;
      }
      p[k] = &staging.World[3 * ids[k]];
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
    // Flat within rounding: 6|V| <= 1e-12 L^3, L the longest edge (the rule of the mesh
    // builder's DegeneracyTolerance). The sign of such a volume is noise: kept with it, a flat
    // tetrahedron could be taken for one overlapping its neighbour and a real tetrahedron left
    // out in its place (torus_vistrails' flat boundary tetrahedra did so: up to 111/255 off).
    double longest = 0.0;
    for (int i = 0; i < 4; ++i)
    {
      for (int j = i + 1; j < 4; ++j)
      {
        const double e[3] = { p[j][0] - p[i][0], p[j][1] - p[i][1], p[j][2] - p[i][2] };
        longest = std::max(longest, e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
      }
    }
    longest = std::sqrt(longest);
    if (!(std::fabs(det) > FlatTolerance * longest * longest * longest) || !std::isfinite(det))
    {
      ++degenerate;
      continue;
    }
    if (det < 0.0)
    {
      std::swap(ids[2], ids[3]);
    }
    staging.Tets.insert(staging.Tets.end(), ids, ids + 4);
    staging.KeptCell.push_back(staging.TetCell[t]);
    double box[6];
    vtkTetReferenceBVH::EmptyBox(box);
    for (int k = 0; k < 4; ++k)
    {
      const double b[6] = { p[k][0], p[k][1], p[k][2], p[k][0], p[k][1], p[k][2] };
      vtkTetReferenceBVH::GrowBox(box, b);
    }
    staging.Boxes.insert(staging.Boxes.end(), box, box + 6);
  }
}

//------------------------------------------------------------------------------
// Tetrahedra on the same side of a face they share overlap: all but the first of each side in
// input order are left out, as the mesh builder does (vtkTetReferenceOverlaps).
void vtkTetReferenceMesh::LeaveOutOverlapping(vtkStaging& staging)
{
  std::vector<vtkIdType>& tets = staging.Tets;
  std::vector<double>& boxes = staging.Boxes;
  std::vector<vtkIdType>& keptCell = staging.KeptCell;
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
}

//------------------------------------------------------------------------------
// The hierarchy (boxes padded far beyond any rounding of the ray frame), and everything stored
// in its order.
void vtkTetReferenceMesh::StoreInHierarchyOrder(vtkStaging& staging)
{
  std::vector<int> order;
  vtkTetReferenceBVH::Build(staging.Boxes, 1e-7 * staging.Diagonal + 1e-300, order, this->Nodes);

  const size_t numTets = staging.KeptCell.size();
  const vtkIdType numPoints = staging.NumberOfPoints;
  const bool cellScalars = staging.CellScalars;
  vtkDataArray* scalars = staging.Scalars;
  this->Points.swap(staging.World);
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
      const vtkIdType id = staging.Tets[4 * static_cast<size_t>(src) + k];
      this->Tets[4 * i + k] = id;
      if (!cellScalars)
      {
        transparent = transparent || !std::isfinite(this->Scalars[id]);
      }
    }
    if (cellScalars)
    {
      const double value = scalars->GetComponent(staging.KeptCell[src], 0);
      this->Scalars[i] = value;
      transparent = !std::isfinite(value);
    }
    this->Transparent[i] = transparent ? 1 : 0;
  }
}
