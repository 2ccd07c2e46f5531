/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshDefectSearch.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetMeshDefectSearch
 * @brief   private: vtkTetMeshBuilder's search for duplicate points and crack faces
 *
 * Duplicate points: points with exactly equal coordinates, found through a hash of the
 * coordinates, sorted with the builder's parallel radix sort. Crack faces: boundary faces that
 * overlap another boundary face made of coincident but distinct points (same plane, facing the
 * other way, interiors intersecting), as along an unwelded seam. Both counts go into the report;
 * they are searched at full builds only.
 */

#ifndef vtkTetMeshDefectSearch_h
#define vtkTetMeshDefectSearch_h

#include "vtkType.h" // For vtkIdType

class vtkTetMeshBuildState;

class vtkTetMeshDefectSearch
{
public:
  /**
   * Count the duplicate points and the crack faces (needs the boundary faces).
   */
  static void FindDuplicatesAndCracks(vtkTetMeshBuildState& state);

private:
  static void SortPointsByHash(vtkTetMeshBuildState& state, int idBits);
  static vtkIdType GroupDuplicatePoints(vtkTetMeshBuildState& state);
  static vtkIdType CountCrackFaces(vtkTetMeshBuildState& state);
};

#endif
// VTK-HeaderTest-Exclude: vtkTetMeshDefectSearch.h
