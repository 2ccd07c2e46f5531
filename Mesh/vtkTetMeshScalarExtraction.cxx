/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshScalarExtraction.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetMeshScalarExtraction.h"
#include "vtkTetMeshSpatialOrder.h"

#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkSMPTools.h"
#include "vtkTetMesh.h"
#include "vtkTetMeshBuildState.h"
#include "vtkTetMeshValidationReport.h"
#include "vtkTetScalarSelection.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

//------------------------------------------------------------------------------
bool vtkTetMeshScalarExtraction::ReadScalars(vtkTetMeshBuildState& state, vtkDataSet* input,
  vtkTetScalarSelection* selection, std::string& error)
{
  vtkTetMesh* mesh = state.Mesh;
  mesh->PointScalars.clear();
  mesh->CellScalars.clear();
  state.InputCellScalars.clear();
  mesh->HasCellScalars = false;
  mesh->ScalarRange[0] = mesh->ScalarRange[1] = 0.0;
  state.GetReport()->SetNumberOfNonFiniteScalars(0);
  state.ScalarsStamp = vtkTetMeshBuildState::Stamp();
  state.ScalarsCellFlag = -1;

  int cellFlag = -1;
  vtkDataArray* array = selection->GetScalars(input, cellFlag);
  if (!array)
  {
    error = DescribeMissingScalars(selection);
    return false;
  }
  if (cellFlag != 0 && cellFlag != 1)
  {
    error = "field-data scalars are not supported: select point or cell data";
    return false;
  }
  const vtkIdType expected = cellFlag == 0 ? input->GetNumberOfPoints() : input->GetNumberOfCells();
  // The rule without a property refuses only a component beyond the array's, which CheckArray
  // words as the mesh builder always has (after the count of values, which it checks first).
  const bool resolved =
    selection->Resolve(array->GetNumberOfComponents(), array->GetName(), nullptr);
  const bool magnitude = resolved && selection->GetMagnitude();
  const int component = resolved ? selection->GetComponent() : selection->GetVectorComponent();
  if (!CheckArray(array, expected, cellFlag, magnitude, component, error))
  {
    return false;
  }

  vtkTetMeshVector<double>& values = cellFlag == 0 ? mesh->PointScalars : state.InputCellScalars;
  values.resize(static_cast<size_t>(expected));
  vtkTetScalarSelection::Extract(array, magnitude, component, values.data());
  if (cellFlag == 0)
  {
    vtkTetMeshSpatialOrder::ApplyPointOrder(mesh, values, 1); // the mesh's point order
  }
  StoreValues(state, cellFlag);
  state.ScalarsStamp = vtkTetMeshBuildState::MakeStamp(array);
  state.ScalarsCellFlag = cellFlag;
  return true;
}

//------------------------------------------------------------------------------
std::string vtkTetMeshScalarExtraction::DescribeMissingScalars(vtkTetScalarSelection* selection)
{
  const int scalarMode = selection->GetScalarMode();
  std::ostringstream text;
  text << "no scalars to render: ";
  if (scalarMode == VTK_SCALAR_MODE_USE_POINT_FIELD_DATA ||
    scalarMode == VTK_SCALAR_MODE_USE_CELL_FIELD_DATA ||
    scalarMode == VTK_SCALAR_MODE_USE_FIELD_DATA)
  {
    const bool byName = selection->GetArrayAccessMode() == VTK_GET_ARRAY_BY_NAME;
    text << "the " << (scalarMode == VTK_SCALAR_MODE_USE_POINT_FIELD_DATA ? "point" : "cell")
         << " data has no numeric array ";
    if (byName)
    {
      text << "named \"" << (selection->GetArrayName() ? selection->GetArrayName() : "") << "\"";
    }
    else
    {
      text << "with index " << selection->GetArrayId();
    }
  }
  else
  {
    text << "the grid has no active "
         << (scalarMode == VTK_SCALAR_MODE_USE_POINT_DATA     ? "point "
                : scalarMode == VTK_SCALAR_MODE_USE_CELL_DATA ? "cell "
                                                              : "point or cell ")
         << "scalars";
  }
  return text.str();
}

//------------------------------------------------------------------------------
// The array holds one tuple per point (cell) and the selected component.
bool vtkTetMeshScalarExtraction::CheckArray(vtkDataArray* array, vtkIdType expected, int cellFlag,
  bool magnitude, int component, std::string& error)
{
  std::ostringstream text;
  const int numComponents = array->GetNumberOfComponents();
  if (array->GetNumberOfTuples() != expected)
  {
    text << "the scalar array \"" << (array->GetName() ? array->GetName() : "") << "\" has "
         << array->GetNumberOfTuples() << " values for " << expected
         << (cellFlag == 0 ? " points" : " cells");
    error = text.str();
    return false;
  }
  if (!magnitude && component >= numComponents)
  {
    text << "component " << component << " was selected from the scalar array \""
         << (array->GetName() ? array->GetName() : "") << "\", which has only " << numComponents;
    error = text.str();
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
// The range of the extracted values (finite ones only), their non-finite count into the report,
// and cell scalars from the input cells to the tetrahedra.
void vtkTetMeshScalarExtraction::StoreValues(vtkTetMeshBuildState& state, int cellFlag)
{
  vtkTetMesh* mesh = state.Mesh;
  const vtkTetMeshVector<double>& values =
    cellFlag == 0 ? mesh->PointScalars : state.InputCellScalars;
  double range[2] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  vtkIdType nonFinite = 0;
  for (double v : values)
  {
    if (std::isfinite(v))
    {
      range[0] = std::min(range[0], v);
      range[1] = std::max(range[1], v);
    }
    else
    {
      ++nonFinite;
    }
  }
  if (range[0] > range[1])
  {
    range[0] = range[1] = 0.0;
  }
  mesh->ScalarRange[0] = range[0];
  mesh->ScalarRange[1] = range[1];
  state.GetReport()->SetNumberOfNonFiniteScalars(nonFinite);
  mesh->HasCellScalars = cellFlag == 1;
  if (mesh->HasCellScalars)
  {
    const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
    mesh->CellScalars.resize(static_cast<size_t>(numTets));
    for (vtkIdType t = 0; t < numTets; ++t)
    {
      mesh->CellScalars[t] = state.InputCellScalars[mesh->TetInputCellIds[t]];
    }
  }
}

//------------------------------------------------------------------------------
void vtkTetMeshScalarExtraction::FlagNonFiniteTets(vtkTetMeshBuildState& state)
{
  vtkTetMesh* mesh = state.Mesh;
  const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
  uint8_t* flags = mesh->TetFlags.data();
  const uint32_t* tp = mesh->TetPoints.data();
  const bool cell = mesh->HasCellScalars;
  const double* s = cell ? mesh->CellScalars.data() : mesh->PointScalars.data();
  const bool any = mesh->HasScalars() && state.GetReport()->GetNumberOfNonFiniteScalars() > 0;
  vtkSMPTools::For(0, numTets, 16384,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType t = begin; t < end; ++t)
      {
        bool bad = false;
        if (any)
        {
          bad = cell ? !std::isfinite(s[t])
                     : !(std::isfinite(s[tp[4 * t]]) && std::isfinite(s[tp[4 * t + 1]]) &&
                         std::isfinite(s[tp[4 * t + 2]]) && std::isfinite(s[tp[4 * t + 3]]));
        }
        flags[t] = bad ? (flags[t] | vtkTetMesh::NonFiniteScalars)
                       : (flags[t] & static_cast<uint8_t>(~vtkTetMesh::NonFiniteScalars));
      }
    });
}
