/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetScalarSelection.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetScalarSelection
 * @brief   which one scalar a (multi-component) array gives a volume property, and refusals
 *
 * The one rule by which the mapper (through vtkTetMeshBuilder) and the exact reference renderer
 * (vtkTetReferenceRenderer) turn the selected scalar array into the one scalar per point or cell
 * that the volume property's first transfer functions are applied to. Resolve() decides, for an
 * array of N components and a vtkVolumeProperty:
 *
 * - N == 1: that component, whatever the settings (as VTK's mappers: the magnitude of one
 *   component is not taken).
 * - N > 1 with IndependentComponentsOff (dependent components: VTK's image mappers read 2
 *   components as colour scalar and opacity scalar, 4 as RGBA; VTK's unstructured mappers do
 *   the same for 2 and 4): refused, with an error. Not rendered here.
 * - N > 1 with IndependentComponentsOn and a colour function of its own set for a component
 *   other than the first (vtkVolumeProperty::SetColor(k, colourFunction), k >= 1: the user asks
 *   for several components blended, as VTK's image mappers do): refused, with an error. Not
 *   rendered here. A gray or opacity function set for component k alone is not seen: the
 *   property cannot tell it from none without creating one (its getters create defaults, and
 *   vtkVolume::SetProperty touches every component's timestamps).
 * - otherwise one value per tuple, chosen by VectorMode: MAGNITUDE (the Euclidean norm) or
 *   COMPONENT (component VectorComponent). DEFAULT, the default, follows VTK 9.1's unstructured
 *   mappers (vtkProjectedTetrahedraMapper): the colour transfer function's own
 *   vtkScalarsToColors::VectorMode and VectorComponent when the property's first component has
 *   an RGB colour function, component 0 when it has a gray one. An explicit MAGNITUDE or
 *   COMPONENT here overrides the colour function. A colour function in RGBCOLORS mode, or a
 *   component beyond the array's, is refused with an error.
 *
 * Extract() then writes the chosen value of every tuple, in double, in parallel, from an array
 * of any numeric type.
 */

#ifndef vtkTetScalarSelection_h
#define vtkTetScalarSelection_h

#include "vtkObject.h"
#include "vtkTiledRayCastIntegrationModule.h" // For export macro

#include <string> // For ErrorMessage

class vtkDataArray;
class vtkVolumeProperty;

class VTKTILEDRAYCASTINTEGRATION_EXPORT vtkTetScalarSelection : public vtkObject
{
public:
  static vtkTetScalarSelection* New();
  vtkTypeMacro(vtkTetScalarSelection, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * How a multi-component array becomes one scalar. MAGNITUDE and COMPONENT have the values of
   * vtkScalarsToColors::MAGNITUDE and COMPONENT.
   */
  enum VectorModes
  {
    DEFAULT = -1,
    MAGNITUDE = 0,
    COMPONENT = 1
  };

  ///@{
  /**
   * The settings (see the class description). Defaults: DEFAULT, component 0 (VectorComponent is
   * used only with VectorMode COMPONENT).
   */
  vtkSetClampMacro(VectorMode, int, DEFAULT, COMPONENT);
  vtkGetMacro(VectorMode, int);
  vtkSetClampMacro(VectorComponent, int, 0, VTK_INT_MAX);
  vtkGetMacro(VectorComponent, int);
  ///@}

  /**
   * Decide how an array of `numberOfComponents` components named `arrayName` (may be null)
   * becomes one scalar under `property` (may be null: then DEFAULT means component 0 and nothing
   * is refused for the property's sake). Returns false, with GetErrorMessage(), when it is not
   * rendered.
   */
  bool Resolve(int numberOfComponents, const char* arrayName, vtkVolumeProperty* property);

  ///@{
  /**
   * The result of the last successful Resolve(): the magnitude, or one component.
   */
  bool GetMagnitude() const { return this->Magnitude; }
  int GetComponent() const { return this->Component; }
  ///@}

  /**
   * Why the last Resolve() refused ("" after a success).
   */
  const char* GetErrorMessage() const { return this->ErrorMessage.c_str(); }

  /**
   * One value per tuple of `array`: its Euclidean norm (`magnitude`) or component `component`
   * (which must exist), as double, into `out` (GetNumberOfTuples() values).
   */
  static void Extract(vtkDataArray* array, bool magnitude, int component, double* out);

protected:
  vtkTetScalarSelection() = default;
  ~vtkTetScalarSelection() override = default;

  int VectorMode = DEFAULT;
  int VectorComponent = 0;

  bool Magnitude = false;
  int Component = 0;
  std::string ErrorMessage;

private:
  vtkTetScalarSelection(const vtkTetScalarSelection&) = delete;
  void operator=(const vtkTetScalarSelection&) = delete;
};

#endif
