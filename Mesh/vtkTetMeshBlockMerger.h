/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshBlockMerger.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetMeshBlockMerger
 * @brief   merges the unstructured-grid blocks of a composite data set into one grid of one scalar
 *
 * How vtkTiledRayCastVolumeMapper renders a vtkMultiBlockDataSet, vtkPartitionedDataSet or
 * vtkPartitionedDataSetCollection (any vtkDataObjectTree) in one traversal: Merge() appends every
 * leaf, in the tree's traversal order, into one vtkUnstructuredGrid holding one scalar per point
 * or cell, which the mesh builder then takes like any grid.
 *
 * - Each block's scalars are selected on their own by the scalar selection (GetScalarSelection(),
 *   the mapper's settings: ScalarMode, ArrayAccessMode, ArrayId/ArrayName: by name, each
 *   block's own array of that name), and reduced to one scalar by its rule with the volume
 *   property, per block. The
 *   merged array (one component, double, named after the first block's array) is the grid's
 *   active point or cell scalars; every block must have its scalars in the same association
 *   (all point data or all cell data).
 * - Points are not merged within a block. A point is merged with a point of an earlier block
 *   when both have exactly the same coordinates and, with point scalars, exactly the same scalar:
 *   the faces blocks share (a partitioned mesh with duplicated interface points) then link, and
 *   rays pass from block to block without a boundary. Where the scalar jumps across the
 *   interface the points stay distinct: the two faces are crack faces of the report, which
 *   rays leave and re-enter exactly (both renderers give one interval each side).
 * - Empty leaves (null, no cells) are skipped and counted. A leaf that is not a
 *   vtkUnstructuredGridBase (image data, polygonal data), a block of polyhedra, a block without
 *   the selected scalars or with them in the other association, and a scalar selection the
 *   property refuses are errors: Merge() returns null and GetErrorMessage() says which block.
 *
 * The merged grid is the same object across calls and is rebuilt only when the tree, a block
 * (its modification time) or a setting changed; a rebuilt grid is a full rebuild for the mesh
 * builder. Cell ids of the merged grid (as the validation report's) count the blocks' cells
 * in traversal order.
 */

#ifndef vtkTetMeshBlockMerger_h
#define vtkTetMeshBlockMerger_h

#include "vtkNew.h" // For vtkNew
#include "vtkObject.h"
#include "vtkTetScalarSelection.h"     // For vtkNew<vtkTetScalarSelection>
#include "vtkTiledRayCastMeshModule.h" // For export macro

#include <memory> // For std::unique_ptr

class vtkDataObjectTree;
class vtkUnstructuredGrid;
class vtkVolumeProperty;

class VTKTILEDRAYCASTMESH_EXPORT vtkTetMeshBlockMerger : public vtkObject
{
public:
  static vtkTetMeshBlockMerger* New();
  vtkTypeMacro(vtkTetMeshBlockMerger, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The scalar selection, applied to each block (VectorMode DEFAULT, the default, follows the
   * property's colour function). Never null.
   */
  vtkTetScalarSelection* GetScalarSelection() { return this->ScalarSelection; }

  /**
   * The merged grid of `input` for `property` (which may be null), or null with
   * GetErrorMessage(). See the class description.
   */
  vtkUnstructuredGrid* Merge(vtkDataObjectTree* input, vtkVolumeProperty* property);

  /**
   * Why the last Merge() failed ("" after a success).
   */
  const char* GetErrorMessage();

  ///@{
  /**
   * Figures of the last successful Merge(): leaves in the tree, empty ones skipped, points
   * merged with a point of an earlier block.
   */
  vtkGetMacro(NumberOfBlocks, vtkIdType);
  vtkGetMacro(NumberOfEmptyBlocks, vtkIdType);
  vtkGetMacro(NumberOfSharedPoints, vtkIdType);
  ///@}

protected:
  vtkTetMeshBlockMerger();
  ~vtkTetMeshBlockMerger() override;

  vtkNew<vtkTetScalarSelection> ScalarSelection;
  vtkIdType NumberOfBlocks = 0;
  vtkIdType NumberOfEmptyBlocks = 0;
  vtkIdType NumberOfSharedPoints = 0;

private:
  vtkTetMeshBlockMerger(const vtkTetMeshBlockMerger&) = delete;
  void operator=(const vtkTetMeshBlockMerger&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
