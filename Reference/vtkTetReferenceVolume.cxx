/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetReferenceVolume.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetReferenceVolume.h"

#include "vtkAbstractMapper.h"
#include "vtkDataSet.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkTetScalarSelection.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

vtkStandardNewMacro(vtkTetReferenceVolume);

//------------------------------------------------------------------------------
vtkTetReferenceVolume::vtkTetReferenceVolume()
  : Matrix(vtkMatrix4x4::New())
  , ScalarMode(VTK_SCALAR_MODE_DEFAULT)
  , ArrayAccessMode(VTK_GET_ARRAY_BY_ID)
  , VectorMode(vtkTetScalarSelection::DEFAULT)
{
}

//------------------------------------------------------------------------------
vtkTetReferenceVolume::~vtkTetReferenceVolume()
{
  this->SetInputData(nullptr);
  this->SetVolumeProperty(nullptr);
  this->SetVolume(nullptr);
  this->SetArrayName(nullptr);
  this->Matrix->Delete();
}

//------------------------------------------------------------------------------
void vtkTetReferenceVolume::SetInputData(vtkDataSet* input)
{
  vtkSetObjectBodyMacro(Input, vtkDataSet, input);
}

//------------------------------------------------------------------------------
vtkCxxSetObjectMacro(vtkTetReferenceVolume, VolumeProperty, vtkVolumeProperty);
vtkCxxSetObjectMacro(vtkTetReferenceVolume, Volume, vtkVolume);

//------------------------------------------------------------------------------
void vtkTetReferenceVolume::SetMatrix(vtkMatrix4x4* matrix)
{
  if (matrix)
  {
    this->Matrix->DeepCopy(matrix);
  }
  else
  {
    this->Matrix->Identity();
  }
  this->Modified();
}

//------------------------------------------------------------------------------
vtkMatrix4x4* vtkTetReferenceVolume::GetMatrix()
{
  return this->Matrix;
}

//------------------------------------------------------------------------------
vtkVolumeProperty* vtkTetReferenceVolume::GetPropertyInForce()
{
  if (this->VolumeProperty)
  {
    return this->VolumeProperty;
  }
  return this->Volume ? this->Volume->GetProperty() : nullptr;
}

//------------------------------------------------------------------------------
void vtkTetReferenceVolume::GetMatrixInForce(double matrix[16])
{
  vtkMatrix4x4::DeepCopy(matrix, this->Volume ? this->Volume->GetMatrix() : this->Matrix);
}

//------------------------------------------------------------------------------
void vtkTetReferenceVolume::SelectScalarArray(int arrayNum)
{
  if (this->ArrayId == arrayNum && this->ArrayAccessMode == VTK_GET_ARRAY_BY_ID)
  {
    return;
  }
  this->ArrayId = arrayNum;
  this->ArrayAccessMode = VTK_GET_ARRAY_BY_ID;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkTetReferenceVolume::SelectScalarArray(const char* arrayName)
{
  if (!arrayName)
  {
    return;
  }
  this->SetArrayName(arrayName);
  this->ArrayAccessMode = VTK_GET_ARRAY_BY_NAME;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkTetReferenceVolume::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Input: " << this->Input << "\n";
  os << indent << "VolumeProperty: " << this->VolumeProperty << "\n";
  os << indent << "Volume: " << this->Volume << "\n";
  os << indent << "ScalarMode: " << this->ScalarMode << "\n";
  os << indent << "ArrayAccessMode: " << this->ArrayAccessMode << "\n";
  os << indent << "ArrayId: " << this->ArrayId << "\n";
  os << indent << "ArrayName: " << (this->ArrayName ? this->ArrayName : "(none)") << "\n";
  os << indent << "VectorMode: " << this->VectorMode << "\n";
  os << indent << "VectorComponent: " << this->VectorComponent << "\n";
  os << indent << "Matrix:\n";
  this->Matrix->PrintSelf(os, indent.GetNextIndent());
}
