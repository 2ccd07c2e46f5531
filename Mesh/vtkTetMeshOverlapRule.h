/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshOverlapRule.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetMeshOverlapRule
 * @brief   private: tetrahedra that overlap through a shared face, and who neighbours whom there
 *
 * Two positively oriented tetrahedra on the same side of a face they share overlap near it (a
 * face shared by three tetrahedra always has two on one side; a cell listed twice has all its
 * faces so). A ray walking from neighbour to neighbour can follow only one of them, and the
 * reference renderer, which has no topology, would composite both: the rule both follow
 * (docs/mesh-layout.md, "non-manifold face") is that on each side of a face the first
 * non-degenerate tetrahedron in input order (lowest input cell id) is kept and every other
 * non-degenerate tetrahedron on that side is left out of the rendering altogether; the two kept
 * ones (one per side) are neighbours. Degenerate tetrahedra (no volume, no side) are never left
 * out, and are linked only where a side has no kept tetrahedron, as before.
 *
 * Used by vtkTetMeshBuilder's face matching for the rare faces shared by more than two
 * tetrahedra or by two on one side; vtkTetReferenceRenderer applies the same rule with code of
 * its own.
 */

#ifndef vtkTetMeshOverlapRule_h
#define vtkTetMeshOverlapRule_h

#include "vtkType.h" // For vtkIdType

#include <cstddef> // For size_t
#include <cstdint> // For uint32_t
#include <vector>  // For std::vector

class vtkTetMeshOverlapRule
{
public:
  /**
   * One tetrahedron's view of a shared face: the face key ((t << 2) | i), the side it lies on
   * (the parity of its outward point order), whether it is degenerate, its input cell.
   */
  struct Entry
  {
    uint32_t Face;
    bool Side;
    bool Degenerate;
    uint32_t InputCell;
  };

  /**
   * For the `m` tetrahedra on one face: the two faces to link (`link`, NoNeighbor where none)
   * and the tetrahedra left out (appended to `leftOut`).
   */
  static void Resolve(const Entry* entries, size_t m, uint32_t link[2], std::vector<uint32_t>& leftOut);

  /**
   * Leave out the tetrahedra of `leftOut` (duplicates allowed): unlink all their faces (their
   * neighbours' faces become boundary faces), flag them `flag`. Returns how many there are.
   */
  static vtkIdType Apply(
    std::vector<uint32_t>& leftOut, uint32_t* neighbors, uint8_t* flags, uint8_t flag);
};

#endif
// VTK-HeaderTest-Exclude: vtkTetMeshOverlapRule.h
