/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetGenMesherSurface.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetGenMesherSurface.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkFeatureEdges.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolygon.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <sstream>
#include <vector>

namespace
{
// A facet whose area is below this fraction of its longest edge squared is degenerate.
constexpr double DegenerateAreaRatio = 1e-12;
}

//------------------------------------------------------------------------------
std::string vtkTetGenMesherSurface::FindDegeneratePolygons(vtkPolyData* input)
{
  vtkIdType degenerate = 0;
  vtkIdType firstDegenerate = -1;
  auto iter = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  std::vector<vtkIdType> ids;
  for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell())
  {
    vtkIdType npts;
    const vtkIdType* pts;
    iter->GetCurrentCell(npts, pts);
    ids.assign(pts, pts + npts);
    std::sort(ids.begin(), ids.end());
    if (std::unique(ids.begin(), ids.end()) - ids.begin() < 3 && degenerate++ == 0)
    {
      firstDegenerate =
        input->GetNumberOfVerts() + input->GetNumberOfLines() + iter->GetCurrentCellId();
    }
  }
  if (degenerate == 0)
  {
    return std::string();
  }
  std::ostringstream message;
  message << "Degenerate input: " << degenerate
          << " polygons have fewer than three distinct points (the first is cell "
          << firstDegenerate << ").";
  return message.str();
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkTetGenMesherSurface::MakeFacets(
  vtkPolyData* input, bool polygonsAsFacets)
{
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  if (polygonsAsFacets && input->GetNumberOfStrips() == 0)
  {
    surface->SetPoints(input->GetPoints());
    surface->SetPolys(input->GetPolys());
    return surface;
  }
  vtkNew<vtkPolyData> faces;
  faces->SetPoints(input->GetPoints());
  faces->SetStrips(input->GetStrips());
  if (!polygonsAsFacets)
  {
    faces->SetPolys(input->GetPolys());
  }
  vtkNew<vtkTriangleFilter> triangles;
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  triangles->SetInputData(faces);
  triangles->Update();
  if (!polygonsAsFacets)
  {
    surface = triangles->GetOutput();
    return surface;
  }
  // The polygons as they are, then the triangles of the strips.
  vtkNew<vtkCellArray> polys;
  polys->DeepCopy(input->GetPolys());
  polys->Append(triangles->GetOutput()->GetPolys());
  surface->SetPoints(input->GetPoints());
  surface->SetPolys(polys);
  return surface;
}

//------------------------------------------------------------------------------
std::string vtkTetGenMesherSurface::FindZeroAreaFacets(vtkPolyData* surface, bool polygonsAsFacets)
{
  vtkCellArray* facets = surface->GetPolys();
  vtkPoints* points = surface->GetPoints();
  vtkSMPThreadLocal<std::vector<vtkIdType>> localDegenerate;
  vtkSMPTools::For(0, facets->GetNumberOfCells(), [&](vtkIdType begin, vtkIdType end) {
    auto iter = vtk::TakeSmartPointer(facets->NewIterator());
    std::vector<vtkIdType>& found = localDegenerate.Local();
    double normal[3];
    for (vtkIdType f = begin; f < end; ++f)
    {
      vtkIdType npts;
      const vtkIdType* pts;
      iter->GetCellAtId(f, npts, pts);
      double longest = 0.0;
      for (vtkIdType i = 0; i < npts; ++i)
      {
        double a[3], b[3];
        points->GetPoint(pts[i], a);
        points->GetPoint(pts[(i + 1) % npts], b);
        longest = std::max(longest, vtkMath::Distance2BetweenPoints(a, b));
      }
      const double area = vtkPolygon::ComputeArea(points, npts, pts, normal);
      if (!(area > DegenerateAreaRatio * longest))
      {
        found.push_back(f);
      }
    }
  });
  std::vector<vtkIdType> degenerate;
  for (const auto& found : localDegenerate)
  {
    degenerate.insert(degenerate.end(), found.begin(), found.end());
  }
  if (degenerate.empty())
  {
    return std::string();
  }
  std::ostringstream message;
  message << "Degenerate input: " << degenerate.size() << " facets have no area (collinear points)"
          << (polygonsAsFacets ? "" : " after triangulation") << "; the first is facet "
          << *std::min_element(degenerate.begin(), degenerate.end()) << ".";
  return message.str();
}

//------------------------------------------------------------------------------
std::string vtkTetGenMesherSurface::FindOpenEdges(vtkPolyData* surface)
{
  // Every edge of a closed, manifold surface bounds exactly two facets.
  vtkNew<vtkFeatureEdges> edges;
  edges->SetInputData(surface);
  edges->FeatureEdgesOff();
  edges->ManifoldEdgesOff();
  edges->ColoringOff();
  edges->BoundaryEdgesOn();
  edges->NonManifoldEdgesOff();
  edges->Update();
  const vtkIdType boundaryEdges = edges->GetOutput()->GetNumberOfCells();
  edges->BoundaryEdgesOff();
  edges->NonManifoldEdgesOn();
  edges->Update();
  const vtkIdType nonManifoldEdges = edges->GetOutput()->GetNumberOfCells();
  if (boundaryEdges == 0 && nonManifoldEdges == 0)
  {
    return std::string();
  }
  std::ostringstream message;
  message << "The surface is not closed: " << boundaryEdges
          << " boundary edges (edges of a single facet) and " << nonManifoldEdges
          << " non-manifold edges (edges of three or more facets). Only a closed, manifold "
             "surface encloses a volume (coincident but distinct points also leave edges "
             "open: vtkCleanPolyData merges them).";
  return message.str();
}
