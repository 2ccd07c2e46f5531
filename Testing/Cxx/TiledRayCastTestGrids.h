/*=========================================================================

  Program:   TiledRayCast
  Module:    TiledRayCastTestGrids.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The small synthetic grids the modules' tests build by hand (the mesh builder's inputs, the
// mapper's faces of three and composite blocks): cells from point ids, arrays from a function,
// and the linear field s = x + 2y + 3z, which any linear split of a cell reproduces exactly.
#ifndef TiledRayCastTestGrids_h
#define TiledRayCastTestGrids_h

#include "vtkCellType.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <array>
#include <initializer_list>
#include <vector>

namespace trctest
{
// Appends a cell of `type` on the points `ids` to `grid`.
inline void AddCell(vtkUnstructuredGrid* grid, int type, const std::vector<vtkIdType>& ids)
{
  grid->InsertNextCell(type, static_cast<vtkIdType>(ids.size()), ids.data());
}

// An array of the values value(0) ... value(n - 1).
template <typename ArrayT, typename Function>
vtkSmartPointer<ArrayT> MakeArray(const char* name, vtkIdType n, Function value)
{
  auto array = vtkSmartPointer<ArrayT>::New();
  array->SetName(name);
  array->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    array->SetValue(i, static_cast<typename ArrayT::ValueType>(value(i)));
  }
  return array;
}

// The point values s = x + 2y + 3z + `offset` of `data`.
inline vtkSmartPointer<vtkDoubleArray> LinearScalars(
  vtkDataSet* data, const char* name = "s", double offset = 0.0)
{
  return MakeArray<vtkDoubleArray>(name, data->GetNumberOfPoints(),
    [data, offset](vtkIdType i)
    {
      double x[3];
      data->GetPoint(i, x);
      return x[0] + 2 * x[1] + 3 * x[2] + offset;
    });
}

// LinearScalars as the active point scalars of `data`.
inline void AddLinearScalars(vtkDataSet* data, const char* name = "s")
{
  data->GetPointData()->SetScalars(LinearScalars(data, name));
}

// A grid of these points and tetrahedra, with linear scalars "s".
inline vtkSmartPointer<vtkUnstructuredGrid> MakeTetGrid(
  std::initializer_list<std::array<double, 3>> points,
  std::initializer_list<std::initializer_list<vtkIdType>> tets)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> gridPoints;
  for (const std::array<double, 3>& p : points)
  {
    gridPoints->InsertNextPoint(p.data());
  }
  grid->SetPoints(gridPoints);
  grid->Allocate(static_cast<vtkIdType>(tets.size()));
  for (const auto& tet : tets)
  {
    AddCell(grid, VTK_TETRA, tet);
  }
  AddLinearScalars(grid);
  return grid;
}
}

#endif
