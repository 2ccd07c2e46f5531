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

#include "vtkSmartPointer.h"       // For vtkSmartPointer
#include "vtkTetReferenceBVH.h"    // For vtkTetReferenceBVH::Node
#include "vtkTetScalarSelection.h" // For vtkSmartPointer<vtkTetScalarSelection>
#include "vtkType.h"               // For vtkIdType, vtkMTimeType

#include <string> // For std::string
#include <vector> // For std::vector

class vtkDataArray;
class vtkDataSet;

class vtkTetReferenceMesh
{
public:
  /**
   * Prepare the mesh from `input` (points through the 4x4 `matrix`), its scalars read by
   * `selection`, resolved (vtkTetScalarSelection::SetVectorModeToResolved(): the array, and a
   * component or the magnitude). False (and `error`) when nothing can be rendered;
   * `degenerate` counts the tetrahedra dropped.
   */
  bool Prepare(vtkDataSet* input, vtkTetScalarSelection* selection, const double matrix[16],
    vtkIdType& degenerate, std::string& error);

  /**
   * Whether the mesh was prepared from this input (unmodified since), the same settings of a
   * resolved selection, and this matrix.
   */
  bool IsPreparedFrom(
    vtkDataSet* input, vtkTetScalarSelection* selection, const double matrix[16]) const;

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
  // The settings of the selection it was prepared with, a copy of its own (a new one at each
  // Prepare(), so that copies of the mesh may share it).
  vtkSmartPointer<vtkTetScalarSelection> Selection;
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
