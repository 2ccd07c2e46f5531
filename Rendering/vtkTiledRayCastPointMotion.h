/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastPointMotion.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastPointMotion
 * @brief   a deforming mesh's points, from the input straight into the GPU's point texels
 *
 * When only the points of the mapper's input moved (same cells, same scalars), the CPU's
 * points-only rebuild (read, reorder and classify every point and tetrahedron, pack the layout's
 * point texels, upload them) is replaced by an upload of the input's coordinates as they are
 * (float or double) and two compute passes (vtkTiledRayCastPointMotionCS.glsl):
 *
 * 1. every tetrahedron is classified as a full build would classify it (orientation and
 *    degeneracy, in double precision, the same arithmetic as vtkTetMeshOrientation), against the
 *    flags the mesh holds, and every coordinate is checked to be finite; the longest edge comes
 *    with it. The counts are read back (a fence, a few bytes): a frame where anything changed is
 *    refused, and the CPU rebuilds it (a full build where a tetrahedron turned inside out), so
 *    that what is drawn always equals a full build of the moved mesh;
 * 2. the mesh points (the input's, in the builder's point order) less the new shift are written
 *    in float into x, y, z of the layout's point texels, in place.
 *
 * The mesh on the CPU keeps the positions of its last build until it is rebuilt (its builder sees
 * the points as changed and catches up). Needs the compact layout's texture buffers, each within
 * a shader storage block, and a current OpenGL 4.3 context (double precision is core since 4.0).
 *
 * Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastPointMotion_h
#define vtkTiledRayCastPointMotion_h

#include "vtkNew.h"                       // For vtkNew
#include "vtkTiledRayCastStorageBuffer.h" // For vtkTiledRayCastStorageBuffer
#include "vtkType.h"                      // For vtkIdType, vtkMTimeType

#include <string> // For std::string

class vtkDataArray;
class vtkOpenGLRenderWindow;
class vtkTetMesh;
class vtkTetMeshLayout;
class vtkTiledRayCastComputeShader;
class vtkTiledRayCastMeshTextures;

class vtkTiledRayCastPointMotion
{
public:
  vtkTiledRayCastPointMotion();
  ~vtkTiledRayCastPointMotion();

  enum Result
  {
    Moved,        // the point texels hold the new points
    NeedsRebuild, // a tetrahedron changed class, or a coordinate is not finite: the CPU rebuilds
    Unavailable   // this mesh or context cannot take this path (GetReason() says why)
  };

  /**
   * Move the points of `mesh` (packed in the compact `layout`, uploaded in `textures`) to
   * `coordinates` (the input's points, 3 components of float or double), shifted by `shift`;
   * `tolerance` is the builder's degeneracy tolerance. On Moved, `longestEdge` is the new
   * longest edge (rounded up to a float's precision) and `uploaded` has the bytes sent added.
   */
  Result Move(vtkOpenGLRenderWindow* window, vtkDataArray* coordinates, vtkTetMesh* mesh,
    vtkTetMeshLayout* layout, const vtkTiledRayCastMeshTextures& textures, double tolerance,
    const double shift[3], double& longestEdge, vtkIdType& uploaded);

  /// Why the last Move() was not Moved.
  const std::string& GetReason() const { return this->Reason; }

  /// Bytes held on the GPU (the input's coordinates, the point order, the flags).
  vtkIdType GetBytes() const;

  /**
   * Delete the GL objects (the context must be current).
   */
  void ReleaseGraphicsResources();

private:
  vtkTiledRayCastPointMotion(const vtkTiledRayCastPointMotion&) = delete;
  void operator=(const vtkTiledRayCastPointMotion&) = delete;

  bool BuildPrograms(bool doubles);
  bool UploadMeshTables(vtkTetMesh* mesh, vtkIdType& uploaded);
  void Dispatch(vtkTiledRayCastComputeShader* program, vtkIdType invocations);

  vtkNew<vtkTiledRayCastComputeShader> Check;
  vtkNew<vtkTiledRayCastComputeShader> Write;
  vtkTiledRayCastStorageBuffer InputPoints;
  vtkTiledRayCastStorageBuffer PointOrder;
  vtkTiledRayCastStorageBuffer Flags;
  vtkTiledRayCastStorageBuffer Findings;
  vtkTiledRayCastStorageBuffer FindingsRead;
  vtkMTimeType OrderTime = 0; // the mesh's topology time when PointOrder was uploaded
  vtkMTimeType FlagsTime = 0; // the mesh's time when Flags was uploaded
  const void* TablesMesh = nullptr;
  std::string Reason;
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastPointMotion.h
