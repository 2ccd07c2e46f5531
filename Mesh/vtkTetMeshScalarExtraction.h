/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshScalarExtraction.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetMeshScalarExtraction
 * @brief   private: vtkTetMeshBuilder's last stage, the scalars and the non-finite tetrahedra
 *
 * ReadScalars takes the scalar array the builder's settings select (vtkAbstractMapper's rule),
 * reduces it to one value per point or cell (vtkTetScalarSelection::Extract), computes the
 * finite range and maps cell scalars to the tetrahedra; it writes the count of NaN/Inf values
 * into the report. FlagNonFiniteTets marks the tetrahedra those values touch.
 */

#ifndef vtkTetMeshScalarExtraction_h
#define vtkTetMeshScalarExtraction_h

#include "vtkType.h" // For vtkIdType

#include <string> // For std::string

class vtkDataArray;
class vtkDataSet;
class vtkTetMeshBuildState;
class vtkTetScalarSelection;

class vtkTetMeshScalarExtraction
{
public:
  /**
   * The scalars `selection` selects from `input` (the builder's: no volume property), into
   * the mesh. False (and `error`) when there are none, or they do not fit the grid or the
   * settings.
   */
  static bool ReadScalars(vtkTetMeshBuildState& state, vtkDataSet* input,
    vtkTetScalarSelection* selection, std::string& error);

  /**
   * Set or clear vtkTetMesh::NonFiniteScalars on every tetrahedron.
   */
  static void FlagNonFiniteTets(vtkTetMeshBuildState& state);

private:
  static std::string DescribeMissingScalars(vtkTetScalarSelection* selection);
  static bool CheckArray(vtkDataArray* array, vtkIdType expected, int cellFlag, bool magnitude,
    int component, std::string& error);
  static void StoreValues(vtkTetMeshBuildState& state, int cellFlag);
};

#endif
// VTK-HeaderTest-Exclude: vtkTetMeshScalarExtraction.h
