/*=========================================================================

  Program:   TiledRayCast
  Module:    BenchmarkMeshOrder.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The memory order of a mesh's cells and points, as the benchmark's --order option changes it:
// the GPU walk fetches a tet's record, its four points and its neighbours' records at every step,
// so how close in memory neighbouring tets lie decides how often those fetches hit the caches.
//   input     the file's order
//   morton    cells along a Morton (Z-order) curve of their centroids, points in the order the
//             sorted cells first use them: neighbours close in memory
//   morton-cells   only the cells sorted so, points in the input order (what the builder's
//             SpatialOrdering does)
//   morton-points  only the points sorted along a Morton curve of their positions
//   shuffled  cells and points in a random order (fixed seed): the worst case, like a mesh
//             assembled from many partitions
#ifndef BenchmarkMeshOrder_h
#define BenchmarkMeshOrder_h

#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <string>

// Whether `order` names one of the orders above.
bool IsMeshOrder(const std::string& order);

// The grid with its cells and points in the given order ("input" returns the grid itself); cell
// and point data follow. Nullptr for an unknown order.
vtkSmartPointer<vtkUnstructuredGrid> ReorderMesh(vtkUnstructuredGrid* grid, const std::string& order);

#endif
