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

#include "vtkSMPTools.h"          // For vtkSMPTools in ApplyPointOrder and MakeKeys
#include "vtkTetMesh.h"           // For vtkTetMesh::GetPointInputIds in ApplyPointOrder
#include "vtkTetMeshBuildState.h" // For vtkTetMeshBuildState::SortKeys in MakeKeys

class vtkTetMeshSpatialOrder
{
public:
  /**
   * Reorder the mesh's tetrahedra (TetPoints, TetInputCellIds) along the Morton curve.
   */
  static void Sort(vtkTetMeshBuildState& state);

  /**
   * Renumber the mesh's points along the Morton curve of their positions (Points permuted,
   * TetPoints remapped, PointInputIds set), so that a tetrahedron's four points lie close in
   * memory: on a billion tetrahedra whose points came in lattice order this made the GPU's
   * traversal 11 times faster. Nothing for 2^31 points or more.
   */
  static void SortPoints(vtkTetMeshBuildState& state);

  /**
   * `values` (`components` per point, in the input's point order) put in the mesh's point
   * order (PointInputIds); nothing when the mesh keeps the input's order.
   */
  template <typename T>
  static void ApplyPointOrder(const vtkTetMesh* mesh, vtkTetMeshVector<T>& values, int components);

  /**
   * state.SortKeys made for items 0 to n - 1, in parallel: item i's key is code(i) (a
   * uint64_t of at most 64 - idBits bits) above i in the low `idBits` bits, the form SortKeys
   * sorts (the Morton orders, the duplicate-point search's hash).
   */
  template <typename Code>
  static void MakeKeys(vtkTetMeshBuildState& state, vtkIdType n, int idBits, Code code);

  /**
   * state.SortKeys sorted by their 33 bits above the low `idBits` (those above bit 63 are
   * none): three counting passes of 11 bits, each in parallel by blocks, stable (ties keep
   * their order) and the same result on any number of threads.
   */
  static void SortKeys(vtkTetMeshBuildState& state, int idBits);

private:
  static void ComputeKeys(vtkTetMeshBuildState& state);
};

//------------------------------------------------------------------------------
template <typename Code>
void vtkTetMeshSpatialOrder::MakeKeys(
  vtkTetMeshBuildState& state, vtkIdType n, int idBits, Code code)
{
  vtkTetMeshVector<uint64_t>& keys = state.SortKeys;
  keys.resize(static_cast<size_t>(n));
  vtkSMPTools::For(0, n, 16384,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        keys[i] = (static_cast<uint64_t>(code(i)) << idBits) | static_cast<uint64_t>(i);
      }
    });
}

//------------------------------------------------------------------------------
template <typename T>
void vtkTetMeshSpatialOrder::ApplyPointOrder(
  const vtkTetMesh* mesh, vtkTetMeshVector<T>& values, int components)
{
  const uint32_t* inputIds = mesh->GetPointInputIds();
  if (!inputIds)
  {
    return;
  }
  vtkTetMeshVector<T> ordered(values.size());
  vtkSMPTools::For(0, mesh->GetNumberOfPoints(), 65536,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        const size_t from = static_cast<size_t>(inputIds[i]) * components;
        for (int c = 0; c < components; ++c)
        {
          ordered[i * components + c] = values[from + c];
        }
      }
    });
  values.swap(ordered);
}

#endif
// VTK-HeaderTest-Exclude: vtkTetMeshSpatialOrder.h
