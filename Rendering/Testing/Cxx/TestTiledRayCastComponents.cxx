/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTiledRayCastComponents.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Multi-component scalars (vtkTetScalarSelection's rule, docs/design.md "The scalar field").
//
// - VTK's TestProjectedTetrahedraVectorComponent scene (a 10x10x10 block of tetrahedra coloured
//   by its point coordinates, a 3-component array, through a colour function set to component 1)
//   renders component 1, checked against the reference told explicitly to take component 1
//   (before the colour function's vector mode was followed: RMSE 5.8, max 33/255 off); the colour
//   function in magnitude mode renders the magnitude; the mapper's own VectorMode overrides the
//   colour function's.
// - What is not rendered is refused with an error, draws nothing, and the reference refuses it
//   too: dependent components (IndependentComponentsOff, 2 and 4 components), a transfer function
//   of its own for a second component (independent components blended), a colour function in
//   RGBCOLORS mode, a component the array does not have.
#include "TiledRayCastTestScene.h"

#include "vtkCellTypeSource.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"

#include <functional>

namespace
{
using trctest::Expect;
using trctest::MessageCounter;

// VTK's TestProjectedTetrahedraVectorComponent data: tetrahedra over [0, 10]^3 and a point array
// "coords" holding each point's coordinates.
vtkSmartPointer<vtkUnstructuredGrid> CoordinatesGrid()
{
  vtkNew<vtkCellTypeSource> source;
  source->SetCellType(VTK_TETRA);
  source->SetBlocksDimensions(10, 10, 10);
  source->Update();
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->ShallowCopy(source->GetOutput());
  vtkNew<vtkDoubleArray> coords;
  coords->SetName("coords");
  coords->DeepCopy(grid->GetPoints()->GetData());
  coords->SetName("coords");
  grid->GetPointData()->AddArray(coords);
  return grid;
}

// That test's property: colour black to green and opacity 0 to 1 over [0, 31], unit distance 4
// (so that rays neither vanish nor saturate over the block).
vtkSmartPointer<vtkVolumeProperty> CoordinatesProperty()
{
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 0.0, 0.0, 0.0);
  color->AddRGBPoint(31.0, 0.0, 1.0, 0.0);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(31.0, 1.0);
  return trcscene::MakeVolumeProperty(color, opacity, 4.0);
}

struct CoordinatesScene
{
  vtkSmartPointer<vtkUnstructuredGrid> Grid = CoordinatesGrid();
  vtkSmartPointer<vtkVolumeProperty> Property = CoordinatesProperty();
  trctest::WatchedVolume View{ Grid, Property, 96 };

  CoordinatesScene()
  {
    vtkTiledRayCastVolumeMapper* mapper = this->View.Mapper;
    mapper->SetScalarModeToUsePointFieldData();
    mapper->SetArrayAccessMode(VTK_GET_ARRAY_BY_NAME);
    mapper->SelectScalarArray("coords");
    this->View.CountErrors();
    vtkCamera* camera = this->View.Renderer->GetActiveCamera();
    camera->Azimuth(30);
    camera->Elevation(20);
    this->View.Renderer->ResetCamera();
  }

  vtkColorTransferFunction* Color() { return this->Property->GetRGBTransferFunction(0); }

  // Renders and compares with the reference told to take `magnitude` or component `component`.
  bool Matches(const std::string& label, bool magnitude, int component)
  {
    this->View.Window->Render();
    bool ok =
      Expect(this->View.Errors->Count == 0, label + ": no error (" + this->View.Errors->Text + ")");
    ok = trctest::CheckAgainstReference(this->View.Window, this->View.Renderer, this->View.Volume,
           trctest::Bounds(), label.c_str(),
           [&](vtkTetReferenceRenderer* reference)
           {
             vtkTetScalarSelection* selection = reference->GetScalarSelection();
             if (magnitude)
             {
               selection->SetVectorModeToMagnitude();
             }
             else
             {
               selection->SetVectorModeToComponent();
               selection->SetVectorComponent(component);
             }
           }) &&
      ok;
    return ok;
  }
};

// The mapper refuses (an error containing `message`, nothing drawn) and so does the reference.
bool Refused(const std::string& label, vtkUnstructuredGrid* grid, vtkVolumeProperty* property,
  const char* message, const std::function<void(vtkTiledRayCastVolumeMapper*)>& configure = nullptr)
{
  trctest::WatchedVolume view(grid, property, 48);
  MessageCounter* errors = view.CountErrors();
  if (configure)
  {
    configure(view.Mapper);
  }
  view.Window->Render();
  view.Window->Render();
  bool ok =
    Expect(errors->Count == 1, label + ": one error (got " + std::to_string(errors->Count) + ")");
  ok = Expect(errors->Text.find(message) != std::string::npos,
         label + ": the error says '" + message + "' (got: " + errors->Text + ")") &&
    ok;
  ok = Expect(!view.Mapper->GetStatistics()->GetRendered(), label + ": nothing drawn") && ok;
  std::cout << label << ": " << errors->Text << "\n";

  vtkNew<vtkTetReferenceRenderer> reference;
  vtkNew<MessageCounter> referenceErrors;
  reference->AddObserver(vtkCommand::ErrorEvent, referenceErrors);
  reference->SetInputData(grid);
  reference->GetScalarSelection()->CopySettings(view.Mapper->GetScalarSelection());
  reference->SetVolumeProperty(property);
  reference->SetCamera(view.Renderer->GetActiveCamera());
  reference->SetImageSize(8, 8);
  ok = Expect(!reference->Render(), label + ": the reference refuses it too") && ok;
  ok = Expect(referenceErrors->Text.find(message) != std::string::npos,
         label + ": the reference's error says '" + message + "'") &&
    ok;
  return ok;
}

// The coordinates grid with its active point scalars an array of `n` components.
vtkSmartPointer<vtkUnstructuredGrid> WithComponents(int n)
{
  auto grid = CoordinatesGrid();
  vtkNew<vtkDoubleArray> values;
  values->SetName("values");
  values->SetNumberOfComponents(n);
  values->SetNumberOfTuples(grid->GetNumberOfPoints());
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    double p[3];
    grid->GetPoint(i, p);
    for (int c = 0; c < n; ++c)
    {
      values->SetComponent(i, c, 0.1 * p[c % 3]);
    }
  }
  grid->GetPointData()->SetScalars(values);
  return grid;
}
}

int TestTiledRayCastComponents(int, char*[])
{
  bool ok = true;
  {
    CoordinatesScene scene;
    scene.Color()->SetVectorModeToComponent();
    scene.Color()->SetVectorComponent(1);
    ok = scene.Matches("colour function, component 1 (VTK's test)", false, 1) && ok;
    scene.Color()->SetVectorComponent(2);
    ok = scene.Matches("colour function, component 2", false, 2) && ok;
    scene.Color()->SetVectorModeToMagnitude();
    ok = scene.Matches("colour function, magnitude", true, 0) && ok;
    // The mapper's own setting wins over the colour function's.
    scene.View.Mapper->SetVectorMode(vtkTiledRayCastVolumeMapper::COMPONENT);
    scene.View.Mapper->SetVectorComponent(0);
    ok = scene.Matches("mapper's component 0 over the colour function's magnitude", false, 0) && ok;
    scene.View.Mapper->SetVectorModeToMagnitude();
    scene.Color()->SetVectorModeToComponent();
    ok = scene.Matches("mapper's magnitude over the colour function's component", true, 0) && ok;
  }

  for (int n : { 2, 4 })
  {
    auto property = CoordinatesProperty();
    property->IndependentComponentsOff();
    ok = Refused("dependent components, " + std::to_string(n), WithComponents(n), property,
           "dependent components") &&
      ok;
  }
  {
    auto property = CoordinatesProperty();
    vtkNew<vtkColorTransferFunction> second;
    second->AddRGBPoint(0.0, 1.0, 0.0, 0.0);
    second->AddRGBPoint(1.0, 1.0, 1.0, 1.0);
    property->SetColor(1, second);
    ok = Refused("a transfer function for component 1", WithComponents(3), property,
           "colour transfer function of its own for component 1") &&
      ok;
  }
  {
    auto property = CoordinatesProperty();
    property->GetRGBTransferFunction(0)->SetVectorModeToRGBColors();
    ok = Refused("RGBCOLORS", WithComponents(3), property, "RGBCOLORS") && ok;
  }
  {
    auto property = CoordinatesProperty();
    property->GetRGBTransferFunction(0)->SetVectorComponent(3);
    ok = Refused("component 3 of 3", WithComponents(3), property, "component 3") && ok;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
