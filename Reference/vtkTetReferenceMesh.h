/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetReferenceMesh.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetReferenceMesh
 * @brief   private: vtkTetReferenceRenderer's preparation, the mesh its rays are cast through
 *
 * Prepare() reads the input with code of the reference's own (it shares only the scalar
 * selection rule, vtkTetScalarSelection, with the mesh builder): the selected scalars reduced
 * to one value, the tetrahedra (split by vtkDataSetTriangleFilter unless the input's 3D cells
 * are all tetrahedra), the points in world coordinates shifted to the centre of their bounds,
 * positive orientation (zero-volume and non-finite tetrahedra dropped), overlapping tetrahedra
 * left out (vtkTetReferenceOverlaps), and the bounding volume hierarchy, the tetrahedra stored in
 * its order.
 */

#ifndef vtkTetReferenceMesh_h
#define vtkTetReferenceMesh_h

#include "vtkTetReferenceBVH.h" // For vtkTetReferenceBVH::Node
#include "vtkType.h"            // For vtkIdType, vtkMTimeType

#include <string> // For std::string
#include <vector> // For std::vector

class vtkDataArray;
class vtkDataSet;

class vtkTetReferenceMesh
{
public:
  /**
   * Which scalars to take from the input (vtkAbstractMapper::GetScalars's arguments) and how to
   * reduce them to one value (vtkTetScalarSelection).
   */
  struct ScalarSettings
  {
    int ScalarMode = -1;
    int ArrayAccessMode = -1;
    int ArrayId = -1;
    std::string ArrayName;
    bool ArrayNameSet = false; // a null name reads as "" above, yet is passed on as null
    bool Magnitude = false;
    int Component = 0;
    bool operator==(const ScalarSettings& o) const
    {
      return this->ScalarMode == o.ScalarMode && this->ArrayAccessMode == o.ArrayAccessMode &&
        this->ArrayId == o.ArrayId && this->ArrayName == o.ArrayName &&
        this->Magnitude == o.Magnitude && this->Component == o.Component;
    }
  };

  /**
   * Prepare the mesh from `input` (points through the 4x4 `matrix`). False (and `error`) when
   * nothing can be rendered; `degenerate` counts the tetrahedra dropped.
   */
  bool Prepare(vtkDataSet* input, const ScalarSettings& settings, const double matrix[16],
    vtkIdType& degenerate, std::string& error);

  /**
   * Whether the mesh was prepared from this input (unmodified since), these settings and matrix.
   */
  bool IsPreparedFrom(
    vtkDataSet* input, const ScalarSettings& settings, const double matrix[16]) const;

  // The prepared mesh, in world coordinates minus Center, tetrahedra in hierarchy order.
  std::vector<double> Points;
  std::vector<vtkIdType> Tets;
  std::vector<double> Scalars; // per point, or per tetrahedron with cell scalars
  bool CellScalars = false;
  std::vector<unsigned char> Transparent;
  std::vector<vtkTetReferenceBVH::Node> Nodes;
  double Center[3] = { 0.0, 0.0, 0.0 };
  size_t NumberOfOverlapping = 0; // tetrahedra left out (vtkTetReferenceOverlaps)

private:
  // What the prepared mesh was built from.
  bool Valid = false;
  vtkDataSet* Input = nullptr;
  vtkMTimeType InputMTime = 0;
  ScalarSettings Settings;
  double Matrix[16];

  class vtkStaging;
  bool CollectTetrahedra(vtkStaging& staging, vtkDataSet* input, std::string& error);
  bool TransformPoints(vtkStaging& staging, const double matrix[16], std::string& error);
  void OrientTetrahedra(vtkStaging& staging, vtkIdType& degenerate);
  void LeaveOutOverlapping(vtkStaging& staging);
  void StoreInHierarchyOrder(vtkStaging& staging);
};

#endif
// VTK-HeaderTest-Exclude: vtkTetReferenceMesh.h
