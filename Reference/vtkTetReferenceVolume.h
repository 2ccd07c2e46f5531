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
 * SetVolumeProperty, the scalar selection, SetVolumeMatrix or SetVolume), said of one more
 * volume of the scene: vtkTetReferenceRenderer::AddVolume() takes any number of them, and the
 * renderer composites all its volumes in one pass in depth order, summing the media where they
 * overlap (docs/design.md, "Overlapping media"). The settings mean what the renderer's mean:
 * scalars chosen as VTK's mappers choose them, reduced to one by vtkTetScalarSelection, lengths
 * in world coordinates after the matrix.
 *
 * @sa vtkTetReferenceRenderer
 */

#ifndef vtkTetReferenceVolume_h
#define vtkTetReferenceVolume_h

#include "vtkObject.h"
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

  ///@{
  /**
   * Which scalars (as vtkTetReferenceRenderer: scalar mode, array by id or name, vector mode
   * and component).
   */
  vtkSetMacro(ScalarMode, int);
  vtkGetMacro(ScalarMode, int);
  void SelectScalarArray(int arrayNum);
  void SelectScalarArray(const char* arrayName);
  vtkSetMacro(ArrayAccessMode, int);
  vtkGetMacro(ArrayAccessMode, int);
  vtkGetMacro(ArrayId, int);
  vtkGetStringMacro(ArrayName);
  vtkSetMacro(VectorMode, int);
  vtkGetMacro(VectorMode, int);
  vtkSetMacro(VectorComponent, int);
  vtkGetMacro(VectorComponent, int);
  ///@}

protected:
  vtkTetReferenceVolume();
  ~vtkTetReferenceVolume() override;

  vtkDataSet* Input = nullptr;
  vtkVolumeProperty* VolumeProperty = nullptr;
  vtkMatrix4x4* Matrix;
  vtkVolume* Volume = nullptr;
  int ScalarMode;
  int ArrayAccessMode;
  int ArrayId = -1;
  char* ArrayName = nullptr;
  int VectorMode;
  int VectorComponent = 0;

private:
  vtkTetReferenceVolume(const vtkTetReferenceVolume&) = delete;
  void operator=(const vtkTetReferenceVolume&) = delete;

  vtkSetStringMacro(ArrayName);
};

#endif
