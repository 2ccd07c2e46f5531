/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetReferenceVolume.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetReferenceVolume
 * @brief   one more volume for vtkTetReferenceRenderer: a mesh, its property, scalars and matrix
 *
 * What vtkTetReferenceRenderer's own settings say of its one input (SetInputData,
 * SetVolumeProperty, GetScalarSelection(), SetVolumeMatrix or SetVolume), said of one more
 * volume of the scene: vtkTetReferenceRenderer::AddVolume() takes any number of them, and the
 * renderer composites all its volumes in one pass in depth order, summing the media where they
 * overlap (docs/design.md, "Overlapping media"). The settings mean what the renderer's mean:
 * scalars chosen as VTK's mappers choose them and reduced to one (vtkTetScalarSelection),
 * lengths in world coordinates after the matrix. The renderer's own settings are those of a
 * volume of this class that it holds.
 *
 * @sa vtkTetReferenceRenderer
 */

#ifndef vtkTetReferenceVolume_h
#define vtkTetReferenceVolume_h

#include "vtkNew.h" // For vtkNew
#include "vtkObject.h"
#include "vtkTetScalarSelection.h"          // For vtkNew<vtkTetScalarSelection>
#include "vtkTiledRayCastReferenceModule.h" // For export macro

class vtkDataSet;
class vtkMatrix4x4;
class vtkVolume;
class vtkVolumeProperty;

class VTKTILEDRAYCASTREFERENCE_EXPORT vtkTetReferenceVolume : public vtkObject
{
public:
  static vtkTetReferenceVolume* New();
  vtkTypeMacro(vtkTetReferenceVolume, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The mesh (any vtkDataSet; as vtkTetReferenceRenderer::SetInputData).
   */
  void SetInputData(vtkDataSet* input);
  vtkGetObjectMacro(Input, vtkDataSet);
  ///@}

  ///@{
  /**
   * The volume property (first component). When none is set, the property of the vtkVolume
   * given with SetVolume() is used.
   */
  void SetVolumeProperty(vtkVolumeProperty* property);
  vtkGetObjectMacro(VolumeProperty, vtkVolumeProperty);
  ///@}

  ///@{
  /**
   * The model-to-world matrix (copied; nullptr means identity, the default). SetVolume() takes
   * the matrix of a vtkVolume at each render instead, and wins over this.
   */
  void SetMatrix(vtkMatrix4x4* matrix);
  vtkMatrix4x4* GetMatrix();
  void SetVolume(vtkVolume* volume);
  vtkGetObjectMacro(Volume, vtkVolume);
  ///@}

  /**
   * The property in force: VolumeProperty, else the vtkVolume's, else null.
   */
  vtkVolumeProperty* GetPropertyInForce();

  /**
   * The matrix in force into `matrix` (row major): the vtkVolume's, else Matrix.
   */
  void GetMatrixInForce(double matrix[16]);

  /**
   * Which scalars are rendered, and how a multi-component array becomes one scalar, as a
   * mapper's (vtkTetScalarSelection: scalar mode, array by index or name, vector mode and
   * component; VectorMode DEFAULT, the default, follows the colour transfer function as VTK's
   * unstructured mappers do). Never null.
   */
  vtkTetScalarSelection* GetScalarSelection() { return this->ScalarSelection; }

  /**
   * The latest of the volume's modification time and its scalar selection's.
   */
  vtkMTimeType GetMTime() override;

protected:
  vtkTetReferenceVolume();
  ~vtkTetReferenceVolume() override;

  vtkDataSet* Input = nullptr;
  vtkVolumeProperty* VolumeProperty = nullptr;
  vtkMatrix4x4* Matrix;
  vtkVolume* Volume = nullptr;
  vtkNew<vtkTetScalarSelection> ScalarSelection;

private:
  vtkTetReferenceVolume(const vtkTetReferenceVolume&) = delete;
  void operator=(const vtkTetReferenceVolume&) = delete;
};

#endif
