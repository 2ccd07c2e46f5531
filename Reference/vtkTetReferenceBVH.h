/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetReferenceBVH.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetReferenceBVH
 * @brief   private: the bounding volume hierarchy vtkTetReferenceRenderer casts its rays through
 *
 * A binned surface area heuristic over the tetrahedra's boxes. Boxes are stored in float,
 * rounded outwards and padded, so that the hierarchy only ever yields a superset of the
 * tetrahedra that a ray meets (the reference's exactness rests on that). Also the few box
 * helpers the reference's preparation shares with it.
 */

#ifndef vtkTetReferenceBVH_h
#define vtkTetReferenceBVH_h

#include <cstdint> // For int32_t
#include <vector>  // For std::vector

class vtkTetReferenceBVH
{
public:
  struct Node
  {
    float Min[3];
    float Max[3];
    int32_t Start; // leaf: first tetrahedron; inner node: index of the first of two children
    int32_t Count; // leaf: number of tetrahedra (> 0); inner node: 0
  };

  static constexpr int LeafSize = 4;
  static constexpr int BinCount = 16;
  static constexpr int MaxBuildDepth = 100;
  // Deep enough for any hierarchy Build() makes (its depth is capped at MaxBuildDepth).
  static constexpr int TraversalStackSize = MaxBuildDepth + 64;

  /**
   * boxes: 6 per item (min xyz, max xyz), each grown by `pad`. `order` gets the item
   * permutation of the leaves, `nodes` the hierarchy (node 0 the root).
   */
  static void Build(const std::vector<double>& boxes, double pad, std::vector<int>& order,
    std::vector<Node>& nodes);

  ///@{
  /**
   * Boxes as 6 doubles (min xyz, max xyz): the empty box, and growing one by another.
   */
  static void EmptyBox(double b[6]);
  static void GrowBox(double b[6], const double* other);
  ///@}

private:
  static int FindSplit(const std::vector<double>& boxes, const std::vector<double>& centroids,
    std::vector<int>& order, int begin, int end, int axis, const double cbox[6]);
};

#endif
// VTK-HeaderTest-Exclude: vtkTetReferenceBVH.h
