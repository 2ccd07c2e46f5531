/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshFaceMatching.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetMeshFaceMatching
 * @brief   private: vtkTetMeshBuilder's face adjacency stage, and the boundary faces
 *
 * Face adjacency without a hash map: faces are bucketed by their smallest point id with a
 * parallel counting sort (each block of tetrahedra owns its slice of every bucket, so no
 * atomics), then the faces of each bucket, a few dozen on average, are paired through a small
 * open-addressing table keyed by their two other ids. A face shared by more than two
 * tetrahedra, or by two on the same side (they overlap), follows vtkTetMeshOverlapRule. Writes
 * the non-manifold face and overlapping tetrahedron counts into the report.
 */

#ifndef vtkTetMeshFaceMatching_h
#define vtkTetMeshFaceMatching_h

#include "vtkTetMesh.h" // For vtkTetMesh::FacePoints in FaceParity

#include <cstdint>    // For uint32_t
#include <functional> // For std::function
#include <vector>     // For std::vector

class vtkTetMeshBuildState;

class vtkTetMeshFaceMatching
{
public:
  /**
   * The mesh's TetNeighbors (needs TetPoints and TetFlags: degenerate tetrahedra have no side).
   * Face entries of more than `scratchLimit` bytes (48 a tetrahedron) are made and matched in
   * four passes over ranges of point ids, a quarter of them at a time; `progress` is called
   * with the fraction done after each pass but the last.
   */
  static void MatchFaces(vtkTetMeshBuildState& state, vtkIdType scratchLimit,
    const std::function<void(double)>& progress);

  /**
   * The mesh's BoundaryFaces: faces without a neighbour, but those of tetrahedra left out.
   */
  static void CollectBoundaryFaces(vtkTetMeshBuildState& state);

  /**
   * Whether the outward order of a face ((t << 2) | i) is an even permutation of its sorted
   * ids. Two positively oriented tetrahedra on opposite sides of a face see it with opposite
   * parities.
   */
  static bool FaceParity(const uint32_t* tetPoints, uint32_t face)
  {
    const uint32_t* ids = tetPoints + 4 * static_cast<size_t>(face >> 2);
    const int* fp = vtkTetMesh::FacePoints[face & 3u];
    const uint32_t a = ids[fp[0]], b = ids[fp[1]], c = ids[fp[2]];
    // Rotate the smallest first; the order is even iff the next one is the middle value.
    if (a < b && a < c)
    {
      return b < c;
    }
    if (b < a && b < c)
    {
      return c < a;
    }
    return a < b;
  }

private:
  // What the passes of PairFaces found.
  struct Pairing
  {
    vtkIdType NonManifold = 0;
    std::vector<uint32_t> LeftOut;
  };
  static void ChunkPasses(
    vtkTetMeshBuildState& state, int passes, vtkTetMeshVector<uint8_t>& chunkPasses);
  static void BucketFaces(vtkTetMeshBuildState& state, uint32_t first, uint32_t last,
    vtkIdType faces, const uint8_t* chunkPasses, uint8_t passBit);
  static uint64_t PrefixSums(vtkTetMeshBuildState& state, int blocks, size_t numPoints);
  static void PairFaces(vtkTetMeshBuildState& state, size_t buckets, Pairing& result);
};

#endif
// VTK-HeaderTest-Exclude: vtkTetMeshFaceMatching.h
