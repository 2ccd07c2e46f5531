/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetGenMesherSurface.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetGenMesherSurface
 * @brief   vtkTetGenMesher's input surface: its facets, and the checks TetGen would fail
 *
 * The steps of vtkTetGenMesher::RequestData before TetGen: the facets TetGen takes (the
 * polygons, triangulated unless kept as facets, and the strips' triangles), and the defects
 * TetGen would answer badly or not at all (polygons with fewer than three distinct points,
 * facets without area, edges that do not bound exactly two facets). Each check returns the
 * message the mesher reports, empty when the surface passes. Private to the module.
 */

#ifndef vtkTetGenMesherSurface_h
#define vtkTetGenMesherSurface_h

#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <string> // For std::string

class vtkPolyData;

class vtkTetGenMesherSurface
{
public:
  /**
   * Polygons of `input` with fewer than three distinct points (which vtkTriangleFilter would
   * drop, leaving a hole), named by the user's cell id.
   */
  static std::string FindDegeneratePolygons(vtkPolyData* input);

  /**
   * The facets: `input`'s polygons as they are (`polygonsAsFacets`) or triangulated, then the
   * triangles of its strips, over `input`'s points.
   */
  static vtkSmartPointer<vtkPolyData> MakeFacets(vtkPolyData* input, bool polygonsAsFacets);

  /**
   * Facets without area (collinear points, or polygons folded onto a line).
   */
  static std::string FindZeroAreaFacets(vtkPolyData* facets, bool polygonsAsFacets);

  /**
   * Edges of a single facet or of three or more: the surface is then not closed and manifold.
   */
  static std::string FindOpenEdges(vtkPolyData* facets);
};

#endif
// VTK-HeaderTest-Exclude: vtkTetGenMesherSurface.h
