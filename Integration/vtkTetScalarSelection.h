/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetScalarSelection.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetScalarSelection
 * @brief   which array a volume renders, which one scalar it gives a volume property, refusals
 *
 * The scalar selection of every renderer of the project, settings and rule, in one place: the
 * mapper hands its own along in one (vtkTiledRayCastVolumeMapper::GetScalarSelection() with
 * CopySettings()), and the mesh builder, the block merger and the exact reference renderer
 * (vtkTetReferenceRenderer, vtkTetReferenceVolume) each hold one (GetScalarSelection()).
 *
 * The array: ScalarMode, ArrayAccessMode, ArrayId and ArrayName, as vtkAbstractVolumeMapper's
 * (VTK_SCALAR_MODE_DEFAULT: the point scalars, else the cell scalars; the field data modes
 * take the array SelectScalarArray() names, by index or by name). GetScalars() finds it in a
 * data set by vtkAbstractMapper::GetScalars, as VTK's mappers do.
 *
 * The one scalar: the rule by which the mapper (through vtkTetMeshBuilder) and the exact
 * reference renderer turn the selected array into the one scalar per point or cell that the
 * volume property's first transfer functions are applied to. Resolve() decides, for an array of
 * N components and a vtkVolumeProperty:
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
 * of any numeric type. SetVectorModeToResolved() makes the decision the settings, for whatever
 * reads the scalars without the property (the mesh builder) or remembers what it read by the
 * settings (the reference renderer's prepared mesh).
 */

#ifndef vtkTetScalarSelection_h
#define vtkTetScalarSelection_h

#include "vtkAbstractMapper.h" // For VTK_SCALAR_MODE_* and VTK_GET_ARRAY_BY_*
#include "vtkObject.h"
#include "vtkTiledRayCastIntegrationModule.h" // For export macro

#include <string> // For ErrorMessage

class vtkDataArray;
class vtkDataSet;
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
   * Which array, as vtkAbstractVolumeMapper: ScalarMode one of VTK_SCALAR_MODE_* (default
   * VTK_SCALAR_MODE_DEFAULT), and with the field data modes the array by index (ArrayId,
   * ArrayAccessMode VTK_GET_ARRAY_BY_ID, the default) or by name (ArrayName,
   * VTK_GET_ARRAY_BY_NAME). SelectScalarArray() sets the index or the name and the access mode
   * with it.
   */
  vtkSetMacro(ScalarMode, int);
  vtkGetMacro(ScalarMode, int);
  void SetScalarModeToDefault() { this->SetScalarMode(VTK_SCALAR_MODE_DEFAULT); }
  void SetScalarModeToUsePointData() { this->SetScalarMode(VTK_SCALAR_MODE_USE_POINT_DATA); }
  void SetScalarModeToUseCellData() { this->SetScalarMode(VTK_SCALAR_MODE_USE_CELL_DATA); }
  void SetScalarModeToUsePointFieldData()
  {
    this->SetScalarMode(VTK_SCALAR_MODE_USE_POINT_FIELD_DATA);
  }
  void SetScalarModeToUseCellFieldData()
  {
    this->SetScalarMode(VTK_SCALAR_MODE_USE_CELL_FIELD_DATA);
  }
  vtkSetMacro(ArrayAccessMode, int);
  vtkGetMacro(ArrayAccessMode, int);
  vtkSetMacro(ArrayId, int);
  vtkGetMacro(ArrayId, int);
  vtkSetStringMacro(ArrayName);
  vtkGetStringMacro(ArrayName);
  void SelectScalarArray(int arrayId);
  void SelectScalarArray(const char* arrayName);
  ///@}

  ///@{
  /**
   * Which one scalar (see the class description). Defaults: DEFAULT, component 0
   * (VectorComponent is used only with VectorMode COMPONENT).
   */
  vtkSetClampMacro(VectorMode, int, DEFAULT, COMPONENT);
  vtkGetMacro(VectorMode, int);
  void SetVectorModeToDefault() { this->SetVectorMode(DEFAULT); }
  void SetVectorModeToMagnitude() { this->SetVectorMode(MAGNITUDE); }
  void SetVectorModeToComponent() { this->SetVectorMode(COMPONENT); }
  vtkSetClampMacro(VectorComponent, int, 0, VTK_INT_MAX);
  vtkGetMacro(VectorComponent, int);
  ///@}

  /**
   * Take the six settings of `source` (not the result of its last Resolve()): how a mapper's or
   * a volume's selection is handed to whatever selects the scalars on its behalf.
   */
  void CopySettings(vtkTetScalarSelection* source);

  /**
   * Whether `other` has the same six settings (a null ArrayName equals ""): how the users that
   * cache what they read tell whether the settings changed.
   */
  bool HasSameSettings(vtkTetScalarSelection* other);

  /**
   * The array the settings select in `input` (vtkAbstractMapper::GetScalars), or null (also
   * for a null `input`). `cellFlag` is GetScalars's: 0 point data, 1 cell data, 2 field data.
   */
  vtkDataArray* GetScalars(vtkDataSet* input, int& cellFlag);

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
   * Make the result of the last Resolve() the settings: VectorMode MAGNITUDE, or COMPONENT with
   * VectorComponent the component (component 0 where Resolve() was never called). The selection
   * then reads the same one scalar without the property.
   */
  void SetVectorModeToResolved();

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
  ~vtkTetScalarSelection() override;

  int ScalarMode = VTK_SCALAR_MODE_DEFAULT;
  int ArrayAccessMode = VTK_GET_ARRAY_BY_ID;
  int ArrayId = -1;
  char* ArrayName = nullptr;
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
