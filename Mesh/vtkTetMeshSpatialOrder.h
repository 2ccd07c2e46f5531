/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshSpatialOrder.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetMeshSpatialOrder
 * @brief   private: vtkTetMeshBuilder's optional stage that sorts tetrahedra along a Morton curve
 *
 * With SpatialOrdering on, the tetrahedra are reordered along a Morton (Z-order) curve of
 * their centroids (11 bits per axis over the mesh's bounds), so that tetrahedra close in space
 * are close in memory; ties keep the input order. TetInputCellIds follows the permutation.
 */

#ifndef vtkTetMeshSpatialOrder_h
#define vtkTetMeshSpatialOrder_h

class vtkTetMeshBuildState;

class vtkTetMeshSpatialOrder
{
public:
  /**
   * Reorder the mesh's tetrahedra (TetPoints, TetInputCellIds) along the Morton curve.
   */
  static void Sort(vtkTetMeshBuildState& state);

private:
  static void ComputeKeys(vtkTetMeshBuildState& state);
  static void SortKeys(vtkTetMeshBuildState& state);
};

#endif
// VTK-HeaderTest-Exclude: vtkTetMeshSpatialOrder.h
