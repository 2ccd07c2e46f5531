/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastEmptySpace.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastEmptySpace
 * @brief   the tetrahedra a transfer function leaves visible, and the faces rays enter them by
 *
 * Empty-space skipping by the transfer function. A tetrahedron is invisible when its scalars
 * (the range of its four point scalars, or its cell scalar) lie where the attenuation is zero:
 * the emission-absorption integral over any segment of it is zero, in every integration mode.
 * The visible tetrahedra form a sub-mesh, non-convex in general (a band of the scalar range is
 * a shell); its boundary faces (faces of visible tetrahedra whose neighbour is missing or
 * invisible) are where rays enter it. The mapper draws those faces instead of the mesh's
 * boundary and its walk leaves the sub-mesh where the next tetrahedron is invisible: each run
 * of invisible tetrahedra along a ray is then crossed in one jump, to the next face of the
 * sub-mesh behind (the depth peeling of non-convex meshes, which both pipelines already do).
 *
 * The test is conservative: a tetrahedron whose scalar range touches the support of the
 * attenuation (its closure, widened by a few float roundings) is visible. Non-finite scalars
 * make a tetrahedron invisible, as the shaders integrate nothing in it.
 *
 * GL-free; recomputed by Update() only when the mesh's topology or scalars or the transfer
 * function changed. Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastEmptySpace_h
#define vtkTiledRayCastEmptySpace_h

#include "vtkType.h" // For vtkIdType, vtkMTimeType

#include <cstdint> // For uint32_t
#include <utility> // For std::pair
#include <vector>  // For std::vector

class vtkTetMesh;
class vtkTiledRayCastTransferFunction;

class vtkTiledRayCastEmptySpace
{
public:
  vtkTiledRayCastEmptySpace() = default;
  ~vtkTiledRayCastEmptySpace() = default;

  /**
   * Classify the tetrahedra of `mesh` against `transferFunction` (null: every tetrahedron is
   * visible, nothing is skipped). Returns true when the result changed since the last call.
   */
  bool Update(vtkTetMesh* mesh, vtkTiledRayCastTransferFunction* transferFunction);

  /**
   * True when some tetrahedron is invisible: the shaders then test visibility and rays enter by
   * GetEntryFaces(). False when every tetrahedron is visible: the mesh's boundary faces serve,
   * and the shaders are those without skipping.
   */
  bool GetSkipsEmptySpace() const { return this->Skips; }

  /**
   * One bit per tetrahedron, 1 when visible, 32 to a word (bit t & 31 of word t >> 5).
   * Empty when GetSkipsEmptySpace() is false.
   */
  const std::vector<uint32_t>& GetVisibleBits() const { return this->VisibleBits; }

  /**
   * The boundary faces of the visible sub-mesh, (t << 2) | face, ordered by tetrahedron then
   * face. Empty when GetSkipsEmptySpace() is false, or when nothing is visible.
   */
  const std::vector<uint32_t>& GetEntryFaces() const { return this->EntryFaces; }

  vtkIdType GetNumberOfVisibleTetrahedra() const { return this->NumberOfVisible; }

  /**
   * Seconds the last classification took (0 when Update() found nothing changed).
   */
  double GetBuildTime() const { return this->BuildTime; }

  /**
   * The closed scalar intervals where the transfer function's attenuation may be positive,
   * sorted and disjoint; +-infinity where the attenuation stays positive beyond the nodes.
   */
  static std::vector<std::pair<double, double>> ComputeSupport(
    vtkTiledRayCastTransferFunction* transferFunction);

private:
  vtkTiledRayCastEmptySpace(const vtkTiledRayCastEmptySpace&) = delete;
  void operator=(const vtkTiledRayCastEmptySpace&) = delete;

  void Classify(vtkTetMesh* mesh, const std::vector<std::pair<double, double>>& support);
  void ListEntryFaces(vtkTetMesh* mesh);

  vtkTetMesh* Mesh = nullptr;
  vtkMTimeType MeshTopologyTime = 0;
  vtkMTimeType MeshScalarsTime = 0;
  vtkMTimeType TransferFunctionTime = 0;
  bool Enabled = false;
  bool Skips = false;
  vtkIdType NumberOfVisible = 0;
  double BuildTime = 0;
  std::vector<uint32_t> VisibleBits;
  std::vector<uint32_t> EntryFaces;
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastEmptySpace.h
