/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastOcclusionQueries.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastOcclusionQueries
 * @brief   a pool of OpenGL occlusion queries, and conditional rendering on them
 *
 * VTK 9.1 has no wrapper for occlusion queries; this small helper keeps the raw GL calls of the
 * mapper's tile and peel termination tests in one place. Queries are created on demand, reused
 * from frame to frame (Recycle() at the start of a frame), and deleted by
 * ReleaseGraphicsResources(). Results can be polled without stalling (IsAvailable) or waited for
 * (GetResult). Conditional rendering lets the GPU itself skip the passes of a tile whose last
 * query counted no active ray, without the CPU ever waiting for the answer.
 *
 * Needs a current OpenGL 3.0+ context. Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastOcclusionQueries_h
#define vtkTiledRayCastOcclusionQueries_h

#include <cstddef> // For size_t
#include <vector>  // For std::vector

class vtkTiledRayCastOcclusionQueries
{
public:
  vtkTiledRayCastOcclusionQueries() = default;
  ~vtkTiledRayCastOcclusionQueries() = default;

  /**
   * Start counting the samples that pass the depth test; returns the query's handle.
   */
  unsigned int Begin();
  void End();

  /**
   * True when the result of a query is ready (never waits).
   */
  bool IsAvailable(unsigned int query) const;

  /**
   * The number of samples counted, waiting for the GPU if needed.
   */
  unsigned int GetResult(unsigned int query) const;

  ///@{
  /**
   * Draw calls between these are skipped by the GPU when the query counted zero samples.
   */
  void BeginConditionalRender(unsigned int query) const;
  void EndConditionalRender() const;
  ///@}

  /**
   * Make every query of the pool available again (call once per frame, after reading the
   * results that are still needed).
   */
  void Recycle() { this->NextFree = 0; }

  /**
   * Queries handed out since the last Recycle().
   */
  size_t GetNumberOfQueriesUsed() const { return this->NextFree; }

  /**
   * Delete the GL query objects (the context must be current).
   */
  void ReleaseGraphicsResources();

private:
  vtkTiledRayCastOcclusionQueries(const vtkTiledRayCastOcclusionQueries&) = delete;
  void operator=(const vtkTiledRayCastOcclusionQueries&) = delete;

  std::vector<unsigned int> Queries;
  size_t NextFree = 0;
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastOcclusionQueries.h
