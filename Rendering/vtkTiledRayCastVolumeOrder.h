/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastVolumeOrder.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastVolumeOrder
 * @brief   the order, farthest first, in which to draw volumes whose world bounds are apart
 *
 * VTK draws a renderer's volumes in the order they were added; each is composited over what is
 * drawn, so a far volume drawn after a near one covers it. This orders boxes (the world bounds
 * of volumes, or of groups of overlapping volumes drawn together) for a camera so that every
 * ray meets them in the order they are drawn, back to front:
 *
 * - Two boxes apart along an axis are separated by a plane across it: the box on the camera's
 *   side of the plane (a perspective camera's position; for a parallel projection, the side
 *   its direction of projection comes from) is the nearer along every ray that meets both,
 *   the camera inside a box or between them included. Where two axes separate them and the
 *   planes disagree, no ray meets both (its path would cross each plane first), and they are
 *   not ordered.
 * - Those pairwise orders are sorted topologically; among the boxes free to come next, the
 *   farthest (the camera's distance to its centre, or its centre's depth along a parallel
 *   projection) comes first, which also orders boxes that overlap (drawn apart, as VTK's own
 *   mappers draw any two volumes). A cycle (three boxes each in front of the next somewhere,
 *   possible with long thin boxes) is broken at its farthest box: the one case where some rays
 *   still meet two volumes out of order.
 *
 * GL-free. Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastVolumeOrder_h
#define vtkTiledRayCastVolumeOrder_h

#include <array>   // For std::array
#include <cstddef> // For std::size_t
#include <vector>  // For std::vector

class vtkCamera;

class vtkTiledRayCastVolumeOrder
{
public:
  using Bounds = std::array<double, 6>; // xmin, xmax, ymin, ymax, zmin, zmax

  /**
   * The indices of `boxes` in the order to draw them for `camera`, farthest first.
   */
  static std::vector<std::size_t> BackToFront(const std::vector<Bounds>& boxes, vtkCamera* camera);

  /**
   * Whether box `a` is in front of box `b` on every ray that meets both (+1), behind (-1), or
   * neither is known (0: they overlap, or no ray meets both). `eye` is the camera's position,
   * or, with `parallel`, its direction of projection.
   */
  static int Compare(const Bounds& a, const Bounds& b, const double eye[3], bool parallel);
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastVolumeOrder.h
