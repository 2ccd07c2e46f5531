/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshPaperLayout.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetMeshPaperLayout
 * @brief   the 144-byte-per-tetrahedron layout of Bernardon et al. 2004 (Figure 8)
 *
 * Three RGBA32F 2D textures of the same size, three texels per tetrahedron in each. Tetrahedron
 * t sits at column u = t % W and rows 3 (t / W) + k, k = 0, 1, 2, where W is the texture width
 * (SetTextureWidth(), default 4096); the height is 3 ceil(T / W), the last texels of the last
 * rows being padding (zeros).
 *
 * | array (index)              | row 3(t/W)          | row 3(t/W)+1        | row 3(t/W)+2        |
 * |----------------------------|---------------------|---------------------|---------------------|
 * | 0 "Vertices"               | v0.x v0.y v0.z v3.x | v1.x v1.y v1.z v3.y | v2.x v2.y v2.z v3.z |
 * | 1 "FaceNormals"            | n0.x n0.y n0.z n3.x | n1.x n1.y n1.z n3.y | n2.x n2.y n2.z n3.z |
 * | 2 "NeighborsAndScalars"    | a0.u a0.v a1.u a1.v | a2.u a2.v a3.u a3.v | g.x g.y g.z c       |
 *
 * - vi: the points of the tetrahedron (positively oriented), minus GetShift();
 * - ni: the unit outward normal of face i (the face opposite vi; a zero-area face has a zero
 *   normal);
 * - ai: the neighbour across face i as the texel coordinates (column, first row) of its first
 *   texel, as floats (exact up to 2^24), or (-1, -1) on a boundary face. As in the paper, the
 *   face of the neighbour through which a ray enters is not stored;
 * - (g, c): the scalar field s(x) = g . x + c with x relative to GetShift(); for cell scalars
 *   and degenerate tetrahedra g = 0; for a tetrahedron touching a NaN or infinite scalar
 *   (transparent) g = 0 and c = +infinity.
 *
 * The paper counts 48 + 48 + 32 + 16 = 144 bytes per tetrahedron; GetNumberOfBytes() is that
 * times the number of texel slots, padding included.
 *
 * The boundary array "BoundaryFaces" (a texture buffer, RGBA32F) has three texels per
 * boundary face: (a.xyz, u), (b.xyz, v), (c.xyz, i), with a, b, c the face's points in outward
 * (counter-clockwise) order minus the shift, (u, v) the texel coordinates of its tetrahedron
 * and i the face index: 48 bytes per boundary face.
 *
 * Build() fails when W or the height exceeds GetMaximumTextureSize().
 */

#ifndef vtkTetMeshPaperLayout_h
#define vtkTetMeshPaperLayout_h

#include "vtkTetMeshLayout.h"
#include "vtkTiledRayCastMeshModule.h" // For export macro

class VTKTILEDRAYCASTMESH_EXPORT vtkTetMeshPaperLayout : public vtkTetMeshLayout
{
public:
  static vtkTetMeshPaperLayout* New();
  vtkTypeMacro(vtkTetMeshPaperLayout, vtkTetMeshLayout);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Array indices.
   */
  enum ArrayIndices
  {
    VerticesArray = 0,
    FaceNormalsArray = 1,
    NeighborsAndScalarsArray = 2
  };

  ///@{
  /**
   * Width W of the three textures in texels (default 4096). Changing it takes a Build().
   */
  vtkSetClampMacro(TextureWidth, int, 1, VTK_INT_MAX);
  vtkGetMacro(TextureWidth, int);
  ///@}

  bool Build(vtkTetMesh* mesh) override;
  bool UpdatePoints(vtkTetMesh* mesh) override;
  bool UpdateScalars(vtkTetMesh* mesh) override;

  /**
   * Texel coordinates (column, first row) of a tetrahedron in the current packing.
   */
  void GetTetTexel(vtkIdType tet, int texel[2]) const;

protected:
  vtkTetMeshPaperLayout();
  ~vtkTetMeshPaperLayout() override;

  void PackGeometry(vtkTetMesh* mesh);
  void PackScalars(vtkTetMesh* mesh);
  void PackBoundary(vtkTetMesh* mesh);

  int TextureWidth = 4096;
  int PackedWidth = 0;

private:
  vtkTetMeshPaperLayout(const vtkTetMeshPaperLayout&) = delete;
  void operator=(const vtkTetMeshPaperLayout&) = delete;
};

#endif
