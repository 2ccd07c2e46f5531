/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetScalarSelection.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetScalarSelection.h"

#include "vtkArrayDispatch.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkDataArrayRange.h"
#include "vtkDataSet.h"
#include "vtkObjectFactory.h"
#include "vtkSMPTools.h"
#include "vtkScalarsToColors.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <cstring>
#include <sstream>

vtkStandardNewMacro(vtkTetScalarSelection);

namespace
{
// One value per tuple out of any numeric array: one component, or the magnitude.
struct ExtractWorker
{
  template <typename ArrayT>
  void operator()(ArrayT* array, double* out, int component, bool magnitude) const
  {
    const auto tuples = vtk::DataArrayTupleRange(array);
    const int numComponents = array->GetNumberOfComponents();
    vtkSMPTools::For(0, array->GetNumberOfTuples(), 8192,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          const auto tuple = tuples[i];
          if (magnitude)
          {
            double sum = 0.0;
            for (int c = 0; c < numComponents; ++c)
            {
              const double v = static_cast<double>(tuple[c]);
              sum += v * v;
            }
            out[i] = std::sqrt(sum);
          }
          else
          {
            out[i] = static_cast<double>(tuple[component]);
          }
        }
      });
  }
};

// Whether component `k` has an RGB colour function of its own (vtkVolumeProperty::SetColor(k,
// colourFunction) makes its ColorChannels 3). Asked without side effects: the property's
// Get...Function(k) would create default functions, and its per-component timestamps are all
// touched by vtkVolume::SetProperty, so a gray or opacity function set for component k alone
// cannot be told from none.
bool HasOwnColorFunction(vtkVolumeProperty* property, int k)
{
  return property->GetColorChannels(k) == 3;
}
}

//------------------------------------------------------------------------------
vtkTetScalarSelection::~vtkTetScalarSelection()
{
  this->SetArrayName(nullptr);
}

//------------------------------------------------------------------------------
// As vtkAbstractVolumeMapper: selecting the array already selected is no change.
void vtkTetScalarSelection::SelectScalarArray(int arrayId)
{
  if (this->ArrayAccessMode == VTK_GET_ARRAY_BY_ID && this->ArrayId == arrayId)
  {
    return;
  }
  this->ArrayId = arrayId;
  this->ArrayAccessMode = VTK_GET_ARRAY_BY_ID;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkTetScalarSelection::SelectScalarArray(const char* arrayName)
{
  if (!arrayName ||
    (this->ArrayAccessMode == VTK_GET_ARRAY_BY_NAME && this->ArrayName &&
      std::strcmp(this->ArrayName, arrayName) == 0))
  {
    return;
  }
  this->SetArrayName(arrayName);
  this->ArrayAccessMode = VTK_GET_ARRAY_BY_NAME;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkTetScalarSelection::CopySettings(vtkTetScalarSelection* source)
{
  if (!source || source == this)
  {
    return;
  }
  // Each setter marks the selection modified only when its value changes, so that handing the
  // same settings along at every render is no change.
  this->SetScalarMode(source->ScalarMode);
  this->SetArrayAccessMode(source->ArrayAccessMode);
  this->SetArrayId(source->ArrayId);
  this->SetArrayName(source->ArrayName);
  this->SetVectorMode(source->VectorMode);
  this->SetVectorComponent(source->VectorComponent);
}

//------------------------------------------------------------------------------
bool vtkTetScalarSelection::HasSameSettings(vtkTetScalarSelection* other)
{
  if (!other)
  {
    return false;
  }
  const char* name = this->ArrayName ? this->ArrayName : "";
  const char* otherName = other->ArrayName ? other->ArrayName : "";
  return this->ScalarMode == other->ScalarMode && this->ArrayAccessMode == other->ArrayAccessMode &&
    this->ArrayId == other->ArrayId && std::strcmp(name, otherName) == 0 &&
    this->VectorMode == other->VectorMode && this->VectorComponent == other->VectorComponent;
}

//------------------------------------------------------------------------------
vtkDataArray* vtkTetScalarSelection::GetScalars(vtkDataSet* input, int& cellFlag)
{
  if (!input)
  {
    return nullptr;
  }
  return vtkAbstractMapper::GetScalars(
    input, this->ScalarMode, this->ArrayAccessMode, this->ArrayId, this->ArrayName, cellFlag);
}

//------------------------------------------------------------------------------
void vtkTetScalarSelection::SetVectorModeToResolved()
{
  this->SetVectorMode(this->Magnitude ? MAGNITUDE : COMPONENT);
  this->SetVectorComponent(this->Component);
}

//------------------------------------------------------------------------------
bool vtkTetScalarSelection::Resolve(
  int numberOfComponents, const char* arrayName, vtkVolumeProperty* property)
{
  this->Magnitude = false;
  this->Component = 0;
  this->ErrorMessage.clear();
  const int n = numberOfComponents;
  if (n <= 1)
  {
    return true;
  }
  std::ostringstream text;
  const std::string name = std::string("the scalar array \"") + (arrayName ? arrayName : "") +
    "\" (" + std::to_string(n) + " components)";
  if (property && !property->GetIndependentComponents())
  {
    text << name
         << " is read with dependent components (vtkVolumeProperty IndependentComponentsOff: "
            "colour and opacity scalars, or RGBA), which this mapper does not render; it renders "
            "one scalar through the first transfer functions (IndependentComponentsOn, with "
            "VectorMode and VectorComponent)";
    this->ErrorMessage = text.str();
    return false;
  }
  if (property)
  {
    for (int k = 1; k < n && k < VTK_MAX_VRCOMP; ++k)
    {
      if (HasOwnColorFunction(property, k))
      {
        text << name << " has a colour transfer function of its own for component " << k
             << " (independent components blended, as VTK's image volume mappers do), which "
                "this mapper does not render; it renders one scalar through the first transfer "
                "functions (VectorMode and VectorComponent)";
        this->ErrorMessage = text.str();
        return false;
      }
    }
  }

  int mode = this->VectorMode;
  int component = this->VectorComponent;
  std::string source = "the mapper's VectorComponent";
  if (mode == DEFAULT)
  {
    mode = COMPONENT;
    component = 0;
    if (property && property->GetColorChannels(0) == 3)
    {
      vtkColorTransferFunction* color = property->GetRGBTransferFunction(0);
      mode = color->GetVectorMode();
      component = color->GetVectorComponent();
      source = "the colour transfer function's VectorComponent";
      if (mode != vtkScalarsToColors::MAGNITUDE && mode != vtkScalarsToColors::COMPONENT)
      {
        text << "the colour transfer function's VectorMode is RGBCOLORS (colours read from " << name
             << "), which this mapper does not render: choose MAGNITUDE or COMPONENT";
        this->ErrorMessage = text.str();
        return false;
      }
    }
  }
  if (mode == MAGNITUDE)
  {
    this->Magnitude = true;
    return true;
  }
  if (component < 0 || component >= n)
  {
    text << "component " << component << " (" << source << ") was selected from " << name;
    this->ErrorMessage = text.str();
    return false;
  }
  this->Component = component;
  return true;
}

//------------------------------------------------------------------------------
void vtkTetScalarSelection::Extract(vtkDataArray* array, bool magnitude, int component, double* out)
{
  ExtractWorker worker;
  if (!vtkArrayDispatch::Dispatch::Execute(array, worker, out, component, magnitude))
  {
    worker(array, out, component, magnitude);
  }
}

//------------------------------------------------------------------------------
void vtkTetScalarSelection::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ScalarMode: " << this->ScalarMode << "\n";
  os << indent << "ArrayAccessMode: " << this->ArrayAccessMode << "\n";
  os << indent << "ArrayId: " << this->ArrayId << "\n";
  os << indent << "ArrayName: " << (this->ArrayName ? this->ArrayName : "(none)") << "\n";
  os << indent << "VectorMode: "
     << (this->VectorMode == DEFAULT ? "Default"
                                     : (this->VectorMode == MAGNITUDE ? "Magnitude" : "Component"))
     << "\n";
  os << indent << "VectorComponent: " << this->VectorComponent << "\n";
  os << indent << "Resolved: "
     << (this->Magnitude ? std::string("magnitude")
                         : "component " + std::to_string(this->Component))
     << "\n";
  os << indent << "ErrorMessage: " << this->ErrorMessage << "\n";
}
