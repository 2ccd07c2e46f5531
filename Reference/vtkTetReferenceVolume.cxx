/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetReferenceVolume.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetReferenceVolume.h"

#include "vtkDataSet.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>

vtkStandardNewMacro(vtkTetReferenceVolume);

//------------------------------------------------------------------------------
vtkTetReferenceVolume::vtkTetReferenceVolume()
  : Matrix(vtkMatrix4x4::New())
{
}

//------------------------------------------------------------------------------
vtkTetReferenceVolume::~vtkTetReferenceVolume()
{
  this->SetInputData(nullptr);
  this->SetVolumeProperty(nullptr);
  this->SetVolume(nullptr);
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
vtkMTimeType vtkTetReferenceVolume::GetMTime()
{
  return std::max(this->Superclass::GetMTime(), this->ScalarSelection->GetMTime());
}

//------------------------------------------------------------------------------
void vtkTetReferenceVolume::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Input: " << this->Input << "\n";
  os << indent << "VolumeProperty: " << this->VolumeProperty << "\n";
  os << indent << "Volume: " << this->Volume << "\n";
  os << indent << "ScalarSelection:\n";
  this->ScalarSelection->PrintSelf(os, indent.GetNextIndent());
  os << indent << "Matrix:\n";
  this->Matrix->PrintSelf(os, indent.GetNextIndent());
}
