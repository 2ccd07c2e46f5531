/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshCellExtraction.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetMeshCellExtraction
 * @brief   private: vtkTetMeshBuilder's first stage, the points and tetrahedra of the input
 *
 * ReadPoints copies the coordinates into the mesh in double precision (refusing NaN and
 * infinite ones) and computes its bounds and shift. ExtractTetrahedra lists the tetrahedra:
 * linear tetrahedra pass through (a parallel copy when the grid holds nothing else), every
 * other 3D cell is split by vtkDataSetTriangleFilter, cells of lower dimension or with bad
 * point ids are left out. It writes the split, ignored and invalid cell counts into the report.
 * See vtkTetMeshBuilder.h for what the input may hold.
 */

#ifndef vtkTetMeshCellExtraction_h
#define vtkTetMeshCellExtraction_h

#include <string> // For std::string

class vtkDataSet;
class vtkTetMeshBuildState;
class vtkUnstructuredGrid;

class vtkTetMeshCellExtraction
{
public:
  /**
   * The input's point coordinates, bounds and shift into the mesh. False (and `error`) when a
   * coordinate is NaN or infinite.
   */
  static bool ReadPoints(vtkTetMeshBuildState& state, vtkDataSet* input, std::string& error);

  /**
   * The input's 3D cells as tetrahedra (mesh TetPoints and TetInputCellIds). False (and
   * `error`) when splitting the non-tetrahedral cells failed.
   */
  static bool ExtractTetrahedra(vtkTetMeshBuildState& state, vtkDataSet* input, std::string& error);

private:
  class vtkCellCollector;
  static void ComputeBounds(vtkTetMeshBuildState& state);
  static bool CopyAllTetrahedra(vtkTetMeshBuildState& state, vtkUnstructuredGrid* grid);
  static void CollectGridCells(vtkCellCollector& collector, vtkUnstructuredGrid* grid);
  static void CollectDataSetCells(vtkCellCollector& collector, vtkDataSet* input);
  static bool SplitCells(vtkCellCollector& collector, std::string& error);
};

#endif
// VTK-HeaderTest-Exclude: vtkTetMeshCellExtraction.h
