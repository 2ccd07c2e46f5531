/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetReferenceOverlaps.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetReferenceOverlaps
 * @brief   private: the reference renderer's own finding of overlapping tetrahedra
 *
 * The rule of vtkTetMeshOverlapRule (docs/mesh-layout.md, "non-manifold face"), written again
 * for vtkTetReferenceRenderer so that the oracle shares no topology code with the mesh builder:
 * two positively oriented, non-degenerate tetrahedra on the same side of a face they share
 * overlap, and every one but the first in input order on each side of a face is left out.
 */

#ifndef vtkTetReferenceOverlaps_h
#define vtkTetReferenceOverlaps_h

#include "vtkType.h" // For vtkIdType

#include <vector> // For std::vector

class vtkTetReferenceOverlaps
{
public:
  /**
   * `tets`: four point ids per tetrahedron, positively oriented, none degenerate, in input
   * order. Returns one flag per tetrahedron, 1 where it is left out.
   */
  static std::vector<unsigned char> Find(const std::vector<vtkIdType>& tets);
};

#endif
// VTK-HeaderTest-Exclude: vtkTetReferenceOverlaps.h
