/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshOrientation.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetMeshOrientation
 * @brief   private: vtkTetMeshBuilder's orientation stages, before and after face matching
 *
 * Classify (before face matching) computes every tetrahedron's signed volume: inverted ones are
 * reoriented (p2 <-> p3) and flagged, degenerate ones (6|V| <= tolerance * L^3) flagged and
 * left as they are. It writes the inverted and degenerate counts and the degenerate input cells
 * into the report. OrientDegenerate (after face matching) turns each degenerate tetrahedron to
 * agree with its oriented neighbours.
 */

#ifndef vtkTetMeshOrientation_h
#define vtkTetMeshOrientation_h

class vtkTetMeshBuildState;

class vtkTetMeshOrientation
{
public:
  /**
   * Orientation and degeneracy of every tetrahedron. With allowFlips false (a points-only
   * update) nothing is reoriented, and the inverted count is left as it is: returns false as
   * soon as a tetrahedron would need reorienting (the builder then does a full build).
   */
  static bool Classify(vtkTetMeshBuildState& state, double tolerance, bool allowFlips);

  /**
   * Each degenerate tetrahedron takes the orientation of its first oriented neighbour (needs
   * the face adjacency).
   */
  static void OrientDegenerate(vtkTetMeshBuildState& state);

private:
  static void CountClassified(vtkTetMeshBuildState& state, bool countInverted);
};

#endif
// VTK-HeaderTest-Exclude: vtkTetMeshOrientation.h
