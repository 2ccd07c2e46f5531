/*=========================================================================

  Program:   TiledRayCast
  Module:    TetGenTestUtilities.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Helpers shared by the vtkTetGenMesher tests: surfaces to mesh (an .off reader, boxes), exact
// measures of a closed surface (enclosed volume, area, Euler characteristic), and the checks that
// every mesh of a surface must pass (tetrahedra only, all positive, volume and boundary equal to
// the surface's). Not a test itself.
#ifndef TetGenTestUtilities_h
#define TetGenTestUtilities_h

#include "TiledRayCastTestCheck.h" // For TRC_CHECK

#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellType.h"
#include "vtkCommand.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkFeatureEdges.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolygon.h"
#include "vtkSmartPointer.h"
#include "vtkTetra.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iostream>
#include <set>
#include <string>
#include <utility>
#include <vector>


namespace trc_tetgen_test
{

/**
 * Reads a Geomview .off polyhedron (as TetGen does: points in double precision, one polygon per
 * face, indices from 0). Returns nullptr when the file cannot be read.
 */
inline vtkSmartPointer<vtkPolyData> ReadOFF(const std::string& fileName)
{
  std::ifstream in(fileName);
  std::string header;
  vtkIdType numberOfPoints = 0, numberOfFaces = 0, numberOfEdges = 0;
  if (!(in >> header >> numberOfPoints >> numberOfFaces >> numberOfEdges) || header != "OFF")
  {
    return nullptr;
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(numberOfPoints);
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    double x[3];
    if (!(in >> x[0] >> x[1] >> x[2]))
    {
      return nullptr;
    }
    points->SetPoint(i, x);
  }
  vtkNew<vtkCellArray> polys;
  std::vector<vtkIdType> ids;
  for (vtkIdType f = 0; f < numberOfFaces; ++f)
  {
    vtkIdType n = 0;
    if (!(in >> n) || n < 1)
    {
      return nullptr;
    }
    ids.resize(n);
    for (auto& id : ids)
    {
      in >> id;
    }
    polys->InsertNextCell(n, ids.data());
  }
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->SetPoints(points);
  surface->SetPolys(polys);
  return in ? surface : nullptr;
}

/**
 * The closed surface of the box [x0,x1]x[y0,y1]x[z0,z1]: 8 points and 12 triangles (or 6 quads),
 * outward oriented.
 */
inline vtkSmartPointer<vtkPolyData> MakeBox(
  double x0, double y0, double z0, double x1, double y1, double z1, bool quads = false)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int k = 0; k < 2; ++k)
  {
    for (int j = 0; j < 2; ++j)
    {
      for (int i = 0; i < 2; ++i)
      {
        points->InsertNextPoint(i ? x1 : x0, j ? y1 : y0, k ? z1 : z0);
      }
    }
  }
  // Point i + 2j + 4k; every quad counter-clockwise seen from outside.
  const vtkIdType faces[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 },
    { 0, 4, 6, 2 }, { 1, 3, 7, 5 } };
  vtkNew<vtkCellArray> polys;
  for (const auto& q : faces)
  {
    if (quads)
    {
      polys->InsertNextCell(4, q);
    }
    else
    {
      const vtkIdType t0[3] = { q[0], q[1], q[2] };
      const vtkIdType t1[3] = { q[0], q[2], q[3] };
      polys->InsertNextCell(3, t0);
      polys->InsertNextCell(3, t1);
    }
  }
  auto box = vtkSmartPointer<vtkPolyData>::New();
  box->SetPoints(points);
  box->SetPolys(polys);
  return box;
}

/**
 * Two surfaces as one polydata (vtkAppendPolyData: the second's points after the first's).
 */
inline vtkSmartPointer<vtkPolyData> Combine(vtkPolyData* a, vtkPolyData* b)
{
  vtkNew<vtkAppendPolyData> append;
  append->AddInputData(a);
  append->AddInputData(b);
  append->Update();
  auto combined = vtkSmartPointer<vtkPolyData>::New();
  combined->ShallowCopy(append->GetOutput());
  return combined;
}

/**
 * Volume enclosed by a closed surface (divergence theorem over a fan of every polygon, around
 * the centre of the bounds to keep rounding small). Sign-free: the orientation of the surface
 * does not matter as long as it is consistent.
 */
inline double EnclosedVolume(vtkPolyData* surface)
{
  double bounds[6];
  surface->GetBounds(bounds);
  const double c[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  double sum = 0.0;
  auto iter = vtk::TakeSmartPointer(surface->GetPolys()->NewIterator());
  for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell())
  {
    vtkIdType npts;
    const vtkIdType* pts;
    iter->GetCurrentCell(npts, pts);
    double a[3];
    surface->GetPoint(pts[0], a);
    for (vtkIdType i = 1; i + 1 < npts; ++i)
    {
      double b[3], d[3];
      surface->GetPoint(pts[i], b);
      surface->GetPoint(pts[i + 1], d);
      double e0[3], e1[3], e2[3];
      for (int k = 0; k < 3; ++k)
      {
        e0[k] = a[k] - c[k];
        e1[k] = b[k] - c[k];
        e2[k] = d[k] - c[k];
      }
      sum += vtkMath::Determinant3x3(e0, e1, e2);
    }
  }
  return std::abs(sum) / 6.0;
}

/**
 * Total area of the polygons of a surface.
 */
inline double SurfaceArea(vtkPolyData* surface)
{
  double area = 0.0;
  double normal[3];
  auto iter = vtk::TakeSmartPointer(surface->GetPolys()->NewIterator());
  for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell())
  {
    vtkIdType npts;
    const vtkIdType* pts;
    iter->GetCurrentCell(npts, pts);
    area += vtkPolygon::ComputeArea(surface->GetPoints(), npts, pts, normal);
  }
  return area;
}

/**
 * Euler characteristic V - E + F of a polygonal surface, counting only the points it uses.
 */
inline vtkIdType EulerCharacteristic(vtkPolyData* surface)
{
  std::set<vtkIdType> vertices;
  std::set<std::pair<vtkIdType, vtkIdType>> edges;
  vtkIdType faces = 0;
  auto iter = vtk::TakeSmartPointer(surface->GetPolys()->NewIterator());
  for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell())
  {
    vtkIdType npts;
    const vtkIdType* pts;
    iter->GetCurrentCell(npts, pts);
    ++faces;
    for (vtkIdType i = 0; i < npts; ++i)
    {
      const vtkIdType a = pts[i], b = pts[(i + 1) % npts];
      vertices.insert(a);
      edges.insert({ std::min(a, b), std::max(a, b) });
    }
  }
  return static_cast<vtkIdType>(vertices.size()) - static_cast<vtkIdType>(edges.size()) + faces;
}

/**
 * Number of boundary plus non-manifold edges of a surface (0 for a closed manifold surface).
 */
inline vtkIdType OpenEdges(vtkPolyData* surface)
{
  vtkNew<vtkFeatureEdges> edges;
  edges->SetInputData(surface);
  edges->FeatureEdgesOff();
  edges->ManifoldEdgesOff();
  edges->BoundaryEdgesOn();
  edges->NonManifoldEdgesOn();
  edges->Update();
  return edges->GetOutput()->GetNumberOfCells();
}

/**
 * The boundary surface of a tetrahedral mesh (its faces that belong to one tetrahedron only).
 * Its point ids are those of the mesh (vtkDataSetSurfaceFilter keeps them in
 * "vtkOriginalPointIds" only; the surface renumbers), so the caller gets both.
 */
inline vtkSmartPointer<vtkPolyData> Boundary(vtkUnstructuredGrid* mesh)
{
  vtkNew<vtkDataSetSurfaceFilter> surface;
  surface->SetInputData(mesh);
  surface->PassThroughPointIdsOn();
  surface->Update();
  return surface->GetOutput();
}

/**
 * What every tetrahedral mesh must satisfy, measured.
 */
struct MeshStatistics
{
  vtkIdType NonTetrahedra = 0;
  vtkIdType NonPositive = 0; // tetrahedra with det[p1-p0, p2-p0, p3-p0] <= 0
  double Volume = 0.0;
  double MinimumVolume = VTK_DOUBLE_MAX;
  double MaximumVolume = 0.0;
};

inline MeshStatistics Measure(vtkUnstructuredGrid* mesh)
{
  MeshStatistics stats;
  auto iter = vtk::TakeSmartPointer(mesh->GetCells()->NewIterator());
  for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell())
  {
    vtkIdType npts;
    const vtkIdType* pts;
    iter->GetCurrentCell(npts, pts);
    if (mesh->GetCellType(iter->GetCurrentCellId()) != VTK_TETRA || npts != 4)
    {
      ++stats.NonTetrahedra;
      continue;
    }
    double p[4][3];
    for (int k = 0; k < 4; ++k)
    {
      mesh->GetPoint(pts[k], p[k]);
    }
    const double volume = vtkTetra::ComputeVolume(p[0], p[1], p[2], p[3]);
    if (!(volume > 0.0))
    {
      ++stats.NonPositive;
    }
    stats.Volume += volume;
    stats.MinimumVolume = std::min(stats.MinimumVolume, volume);
    stats.MaximumVolume = std::max(stats.MaximumVolume, volume);
  }
  return stats;
}

inline double RelativeDifference(double a, double b)
{
  return std::abs(a - b) / std::max(std::abs(a), std::abs(b));
}

/**
 * Records the error and warning messages of an algorithm (and keeps them off the output window,
 * whose "ERROR:" text would fail the test).
 */
class MessageRecorder : public vtkCommand
{
public:
  static MessageRecorder* New() { return new MessageRecorder; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    const std::string text = data ? static_cast<const char*>(data) : "";
    (event == vtkCommand::ErrorEvent ? this->Errors : this->Warnings).push_back(text);
  }
  bool ErrorContains(const std::string& part) const
  {
    return std::any_of(this->Errors.begin(), this->Errors.end(),
      [&](const std::string& e) { return e.find(part) != std::string::npos; });
  }
  void Clear()
  {
    this->Errors.clear();
    this->Warnings.clear();
  }
  std::vector<std::string> Errors;
  std::vector<std::string> Warnings;
};

} // namespace trc_tetgen_test

#endif
