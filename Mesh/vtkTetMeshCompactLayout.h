/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshCompactLayout.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetMeshCompactLayout
 * @brief   32 bytes per tetrahedron plus 16 per point: indices, with geometry shared
 *
 * Texture buffers, one texel per tetrahedron or per point:
 *
 * | array (index)      | format   | texels | texel                                          |
 * |--------------------|----------|--------|------------------------------------------------|
 * | 0 "TetPoints"      | RGBA32UI | T      | point ids p0 p1 p2 p3 (positively oriented)     |
 * | 1 "TetNeighbors"   | RGBA32UI | T      | neighbour words (n << 2) \| j, or 0xFFFFFFFF    |
 * | 2 "Points"         | RGBA32F  | N      | x y z s, x relative to GetShift()               |
 * | 3 "TetScalars"     | R32F     | T      | the cell value (only with cell scalars)         |
 *
 * Arrays 0 and 1 are the mesh's own (vtkTetMesh::GetTetPointsArray(), GetTetNeighborsArray()),
 * shared rather than copied: 32 bytes a tetrahedron the host does not hold twice.
 *
 * With point scalars, s is the point's value; a NaN or infinite value is stored as +infinity
 * (compares reliably in shaders; NaN may not), and a tetrahedron with such a vertex is
 * transparent. With cell scalars, s is 0 and a fourth, one-component array holds one value per
 * tetrahedron (+infinity for a non-finite one): 4 more bytes per tetrahedron.
 *
 * Face normals and the scalar gradient are not stored: the shader computes them from the four
 * points (face i is the one opposite point i, its points in the outward order of
 * vtkTetMesh::GetFacePointIndices()), trading a few dozen flops for 112 bytes per tetrahedron.
 * Entering neighbour n through its face j, the shader knows which face not to test.
 *
 * The boundary array "BoundaryFaces" (texture buffer, RGBA32UI) holds one texel per boundary
 * face: its three point ids in outward (counter-clockwise) order and the face word (t << 2) | i.
 * A vertex shader can draw the faces without a vertex buffer: face = gl_VertexID / 3, point id
 * from the face's texel, position from "Points".
 *
 * An array of more than GetMaximumTextureBufferSize() texels is split over texture buffers of
 * GetTextureBufferSize() texels; Build() fails when one needs more than
 * GetMaximumTextureBuffersPerArray() of them.
 */

#ifndef vtkTetMeshCompactLayout_h
#define vtkTetMeshCompactLayout_h

#include "vtkTetMeshLayout.h"
#include "vtkTiledRayCastMeshModule.h" // For export macro

class VTKTILEDRAYCASTMESH_EXPORT vtkTetMeshCompactLayout : public vtkTetMeshLayout
{
public:
  static vtkTetMeshCompactLayout* New();
  vtkTypeMacro(vtkTetMeshCompactLayout, vtkTetMeshLayout);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Array indices (TetScalarsArray exists only with cell scalars).
   */
  enum ArrayIndices
  {
    TetPointsArray = 0,
    TetNeighborsArray = 1,
    PointsArray = 2,
    TetScalarsArray = 3
  };

  bool Build(vtkTetMesh* mesh) override;
  bool UpdatePoints(vtkTetMesh* mesh) override;
  bool UpdateScalars(vtkTetMesh* mesh) override;

protected:
  vtkTetMeshCompactLayout();
  ~vtkTetMeshCompactLayout() override;

  void PackPoints(vtkTetMesh* mesh);
  void PackCellScalars(vtkTetMesh* mesh);
  bool NeedsBuild(vtkTetMesh* mesh);

  ArrayInfo CellScalars;

private:
  vtkTetMeshCompactLayout(const vtkTetMeshCompactLayout&) = delete;
  void operator=(const vtkTetMeshCompactLayout&) = delete;
};

#endif
