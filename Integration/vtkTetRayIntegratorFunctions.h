/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetRayIntegratorFunctions.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetRayIntegratorFunctions
 * @brief   private: one copy of a volume property's transfer functions, as vtkTetRayIntegrator
 *          evaluates them
 *
 * The integrator works on copies (a snapshot, and one per thread: VTK does not promise that
 * evaluating a function from several threads is safe), made so that they evaluate exactly like
 * the originals; Evaluate gives the attenuation (per unit length) and the colour at a scalar.
 */

#ifndef vtkTetRayIntegratorFunctions_h
#define vtkTetRayIntegratorFunctions_h

#include "vtkColorTransferFunction.h"              // For vtkColorTransferFunction
#include "vtkDiscretizableColorTransferFunction.h" // For the discretization of a copy
#include "vtkPiecewiseFunction.h"     // For vtkPiecewiseFunction
#include "vtkSmartPointer.h"          // For vtkSmartPointer

#include <algorithm> // For std::max

class vtkTetRayIntegratorFunctions
{
public:
  vtkSmartPointer<vtkColorTransferFunction> Color; // null when the gray function is used
  vtkSmartPointer<vtkPiecewiseFunction> Gray;
  vtkSmartPointer<vtkPiecewiseFunction> Opacity;
  double InverseUnitDistance = 1.0;

  // tau is clamped at 0: a negative attenuation has no physical meaning and would let the
  // transmittance grow without bound.
  void Evaluate(double s, double& tau, double c[3])
  {
    tau = std::max(0.0, this->Opacity->GetValue(s)) * this->InverseUnitDistance;
    if (this->Color)
    {
      this->Color->GetColor(s, c);
    }
    else
    {
      c[0] = c[1] = c[2] = this->Gray->GetValue(s);
    }
  }

  static vtkSmartPointer<vtkPiecewiseFunction> Clone(vtkPiecewiseFunction* f)
  {
    vtkSmartPointer<vtkPiecewiseFunction> copy = vtkSmartPointer<vtkPiecewiseFunction>::Take(
      vtkPiecewiseFunction::SafeDownCast(f->NewInstance()));
    // Duplicate nodes survive DeepCopy only if the copy allows them before the nodes arrive.
    copy->SetAllowDuplicateScalars(f->GetAllowDuplicateScalars());
    copy->DeepCopy(f);
    copy->SetClamping(f->GetClamping());
    copy->SetUseLogScale(f->GetUseLogScale());
    return copy;
  }

  static vtkSmartPointer<vtkColorTransferFunction> Clone(vtkColorTransferFunction* f)
  {
    vtkSmartPointer<vtkColorTransferFunction> copy =
      vtkSmartPointer<vtkColorTransferFunction>::Take(
        vtkColorTransferFunction::SafeDownCast(f->NewInstance()));
    copy->SetAllowDuplicateScalars(f->GetAllowDuplicateScalars());
    copy->DeepCopy(f);
    // What DeepCopy may leave out, depending on the VTK version.
    copy->SetClamping(f->GetClamping());
    copy->SetColorSpace(f->GetColorSpace());
    copy->SetHSVWrap(f->GetHSVWrap());
    copy->SetScale(f->GetScale());
    copy->SetNanColor(f->GetNanColor());
    copy->SetBelowRangeColor(f->GetBelowRangeColor());
    copy->SetUseBelowRangeColor(f->GetUseBelowRangeColor());
    copy->SetAboveRangeColor(f->GetAboveRangeColor());
    copy->SetUseAboveRangeColor(f->GetUseAboveRangeColor());
    // VTK 9.1's DeepCopy of a discretizable map leaves out its discretization (a copy of
    // ParaView's default map would be smooth) and its lookup table is built on demand.
    auto* discrete = vtkDiscretizableColorTransferFunction::SafeDownCast(f);
    auto* discreteCopy = vtkDiscretizableColorTransferFunction::SafeDownCast(copy);
    if (discrete && discreteCopy)
    {
      discreteCopy->SetDiscretize(discrete->GetDiscretize());
      discreteCopy->SetNumberOfValues(discrete->GetNumberOfValues());
      discreteCopy->SetIndexedLookup(discrete->GetIndexedLookup());
      discreteCopy->SetUseLogScale(discrete->GetUseLogScale());
      discrete->Build();
      discreteCopy->Build();
    }
    return copy;
  }

  void CopyFrom(const vtkTetRayIntegratorFunctions& other)
  {
    this->Color = other.Color ? Clone(other.Color) : nullptr;
    this->Gray = other.Gray ? Clone(other.Gray) : nullptr;
    this->Opacity = Clone(other.Opacity);
    this->InverseUnitDistance = other.InverseUnitDistance;
  }
};

#endif
// VTK-HeaderTest-Exclude: vtkTetRayIntegratorFunctions.h
