/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetReferenceRayCaster.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetReferenceRayCaster
 * @brief   private: every tetrahedron a ray crosses, exactly, and where
 *
 * vtkTetReferenceRenderer has no topology to walk: each ray goes down the bounding volume
 * hierarchy of the prepared mesh (vtkTetReferenceMesh) and is tested against every tetrahedron
 * of the leaves it meets. The test is exact where it decides (which faces the ray enters and
 * leaves through: exact orientation of each edge against the ray, vtkTetExactArithmetic.h),
 * in a ray frame where each shared vertex is transformed bitwise the same for every tetrahedron
 * that uses it, so that neighbours agree on their shared face: no gap, no double count. The
 * hits come back sorted front to back, for compositing (vtkTetReferenceCompositing).
 */

#ifndef vtkTetReferenceRayCaster_h
#define vtkTetReferenceRayCaster_h

#include "vtkType.h" // For vtkIdType

#include <vector> // For std::vector

class vtkTetReferenceMesh;

class vtkTetReferenceRayCaster
{
public:
  /**
   * One tetrahedron crossed by a ray: the ray parameters where it enters and leaves (clipped to
   * the ray's range), the scalars there, and the tetrahedron. Ordered front to back.
   */
  struct Hit
  {
    double Z0, Z1, S0, S1;
    vtkIdType Tet;
    bool operator<(const Hit& o) const
    {
      if (this->Z0 != o.Z0)
      {
        return this->Z0 < o.Z0;
      }
      if (this->Z1 != o.Z1)
      {
        return this->Z1 < o.Z1;
      }
      return this->Tet < o.Tet;
    }
  };

  /**
   * The tetrahedra of `mesh` that the ray origin + z d crosses for z in (zmin, zmax), sorted.
   */
  static void CastRay(const vtkTetReferenceMesh& mesh, const double origin[3], const double d[3],
    double zmin, double zmax, std::vector<Hit>& hits);

private:
  class vtkRayFrame;
  static bool CrossTetrahedron(const vtkTetReferenceMesh& mesh, const vtkRayFrame& frame,
    vtkIdType tet, double zmin, double zmax, Hit& hit);
};

#endif
// VTK-HeaderTest-Exclude: vtkTetReferenceRayCaster.h
