/*=========================================================================

  Program:   TiledRayCast
  Module:    BenchmarkMeshOrder.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "BenchmarkMeshOrder.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

namespace
{
// 21 bits of each coordinate interleaved.
std::uint64_t MortonCode(const double x[3], const double bounds[6])
{
  std::uint64_t code = 0;
  std::uint64_t cell[3];
  for (int a = 0; a < 3; ++a)
  {
    const double extent = bounds[2 * a + 1] - bounds[2 * a];
    const double t = extent > 0 ? (x[a] - bounds[2 * a]) / extent : 0.0;
    cell[a] = static_cast<std::uint64_t>(std::min(std::max(t, 0.0), 1.0) * 2097151.0);
  }
  for (int bit = 20; bit >= 0; --bit)
  {
    for (int a = 0; a < 3; ++a)
    {
      code = (code << 1) | ((cell[a] >> bit) & 1u);
    }
  }
  return code;
}
}

bool IsMeshOrder(const std::string& order)
{
  return order == "input" || order == "morton" || order == "morton-cells" ||
    order == "morton-points" || order == "shuffled";
}

vtkSmartPointer<vtkUnstructuredGrid> ReorderMesh(vtkUnstructuredGrid* grid, const std::string& order)
{
  if (order == "input")
  {
    return grid;
  }
  if (!IsMeshOrder(order))
  {
    return nullptr;
  }
  const vtkIdType numCells = grid->GetNumberOfCells();
  const vtkIdType numPoints = grid->GetNumberOfPoints();
  std::vector<vtkIdType> cells(numCells);
  std::iota(cells.begin(), cells.end(), 0);
  std::vector<vtkIdType> newPointOf(numPoints, -1);
  std::vector<vtkIdType> points; // old ids in new order
  points.reserve(numPoints);
  vtkNew<vtkIdList> ids;
  std::mt19937_64 random(20261202);
  if (order != "shuffled")
  {
    double bounds[6];
    grid->GetBounds(bounds);
    if (order != "morton-points")
    {
      std::vector<std::uint64_t> codes(numCells);
      for (vtkIdType c = 0; c < numCells; ++c)
      {
        grid->GetCellPoints(c, ids);
        double centroid[3] = { 0, 0, 0 };
        for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
        {
          double x[3];
          grid->GetPoint(ids->GetId(k), x);
          for (int a = 0; a < 3; ++a)
          {
            centroid[a] += x[a] / ids->GetNumberOfIds();
          }
        }
        codes[c] = MortonCode(centroid, bounds);
      }
      std::stable_sort(
        cells.begin(), cells.end(), [&](vtkIdType a, vtkIdType b) { return codes[a] < codes[b]; });
    }
    if (order == "morton")
    {
      // Points in the order the sorted cells first use them.
      for (vtkIdType c : cells)
      {
        grid->GetCellPoints(c, ids);
        for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
        {
          vtkIdType& id = newPointOf[ids->GetId(k)];
          if (id < 0)
          {
            id = static_cast<vtkIdType>(points.size());
            points.push_back(ids->GetId(k));
          }
        }
      }
      for (vtkIdType p = 0; p < numPoints; ++p) // points no cell uses, last
      {
        if (newPointOf[p] < 0)
        {
          newPointOf[p] = static_cast<vtkIdType>(points.size());
          points.push_back(p);
        }
      }
    }
    else
    {
      // Points in their input order (morton-cells), or along their own Morton curve.
      points.resize(numPoints);
      std::iota(points.begin(), points.end(), 0);
      if (order == "morton-points")
      {
        std::vector<std::uint64_t> codes(numPoints);
        for (vtkIdType p = 0; p < numPoints; ++p)
        {
          codes[p] = MortonCode(grid->GetPoint(p), bounds);
        }
        std::stable_sort(points.begin(), points.end(),
          [&](vtkIdType a, vtkIdType b) { return codes[a] < codes[b]; });
      }
      for (vtkIdType p = 0; p < numPoints; ++p)
      {
        newPointOf[points[p]] = p;
      }
    }
  }
  else
  {
    std::shuffle(cells.begin(), cells.end(), random);
    points.resize(numPoints);
    std::iota(points.begin(), points.end(), 0);
    std::shuffle(points.begin(), points.end(), random);
    for (vtkIdType p = 0; p < numPoints; ++p)
    {
      newPointOf[points[p]] = p;
    }
  }

  auto result = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> newPoints;
  newPoints->SetDataType(grid->GetPoints()->GetDataType());
  newPoints->SetNumberOfPoints(numPoints);
  vtkPointData* pointData = result->GetPointData();
  pointData->CopyAllocate(grid->GetPointData(), numPoints);
  for (vtkIdType p = 0; p < numPoints; ++p)
  {
    newPoints->SetPoint(p, grid->GetPoint(points[p]));
    pointData->CopyData(grid->GetPointData(), points[p], p);
  }
  result->SetPoints(newPoints);
  result->Allocate(numCells);
  vtkCellData* cellData = result->GetCellData();
  cellData->CopyAllocate(grid->GetCellData(), numCells);
  vtkNew<vtkIdList> renumbered;
  for (vtkIdType c = 0; c < numCells; ++c)
  {
    grid->GetCellPoints(cells[c], ids);
    renumbered->SetNumberOfIds(ids->GetNumberOfIds());
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      renumbered->SetId(k, newPointOf[ids->GetId(k)]);
    }
    result->InsertNextCell(grid->GetCellType(cells[c]), renumbered);
    cellData->CopyData(grid->GetCellData(), cells[c], c);
  }
  return result;
}
