/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastMeshInput.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastMeshInput.h"

#include "vtkAbstractMapper.h"
#include "vtkDataArray.h"
#include "vtkDataObjectTree.h"
#include "vtkDataSet.h"
#include "vtkTetMeshBlockMerger.h"
#include "vtkTetMeshBuilder.h"
#include "vtkTetMeshValidationReport.h"
#include "vtkTetScalarSelection.h"
#include "vtkTiledRayCastVolumeMapper.h"
#include "vtkUnstructuredGrid.h"

//------------------------------------------------------------------------------
vtkTiledRayCastMeshInput::vtkTiledRayCastMeshInput()
  : Merger(vtkTetMeshBlockMerger::New())
{
}

//------------------------------------------------------------------------------
vtkTiledRayCastMeshInput::~vtkTiledRayCastMeshInput()
{
  this->Merger->Delete();
}

//------------------------------------------------------------------------------
vtkDataSet* vtkTiledRayCastMeshInput::Prepare(vtkTiledRayCastVolumeMapper* mapper,
  vtkDataObject* input, vtkVolumeProperty* property, vtkTetMeshBuilder* builder,
  std::string& error)
{
  this->Composite = false;
  if (vtkDataObjectTree* tree = vtkDataObjectTree::SafeDownCast(input))
  {
    this->Composite = true;
    vtkTetMeshBlockMerger* merger = this->Merger;
    merger->SetScalarMode(mapper->GetScalarMode());
    merger->SetArrayAccessMode(mapper->GetArrayAccessMode());
    merger->SetArrayId(mapper->GetArrayId());
    merger->SetArrayName(mapper->GetArrayName());
    merger->SetVectorMode(mapper->GetVectorMode());
    merger->SetVectorComponent(mapper->GetVectorComponent());
    vtkUnstructuredGrid* merged = merger->Merge(tree, property);
    if (!merged)
    {
      error = std::string("Cannot render the composite input: ") + merger->GetErrorMessage();
      return nullptr;
    }
    // The merged grid's active scalars are the one scalar to render.
    builder->SetScalarMode(VTK_SCALAR_MODE_DEFAULT);
    builder->SetArrayAccessMode(VTK_GET_ARRAY_BY_ID);
    builder->SetArrayId(-1);
    builder->SetArrayName(nullptr);
    builder->SetVectorModeToComponent();
    builder->SetVectorComponent(0);
    return merged;
  }

  vtkDataSet* grid = vtkDataSet::SafeDownCast(input);
  builder->SetScalarMode(mapper->GetScalarMode());
  builder->SetArrayAccessMode(mapper->GetArrayAccessMode());
  builder->SetArrayId(mapper->GetArrayId());
  builder->SetArrayName(mapper->GetArrayName());
  // The one scalar the property takes from the array (vtkTetScalarSelection's rule, which the
  // reference renderer follows too); a missing array is the builder's error.
  int cellFlag = -1;
  vtkDataArray* array = grid ? vtkAbstractMapper::GetScalars(grid, mapper->GetScalarMode(),
                                 mapper->GetArrayAccessMode(), mapper->GetArrayId(),
                                 mapper->GetArrayName(), cellFlag)
                             : nullptr;
  vtkNew<vtkTetScalarSelection> selection;
  selection->SetVectorMode(mapper->GetVectorMode());
  selection->SetVectorComponent(mapper->GetVectorComponent());
  if (array && !selection->Resolve(array->GetNumberOfComponents(), array->GetName(), property))
  {
    error = std::string("Not rendered: ") + selection->GetErrorMessage();
    return nullptr;
  }
  builder->SetVectorMode(
    selection->GetMagnitude() ? vtkTetMeshBuilder::Magnitude : vtkTetMeshBuilder::Component);
  builder->SetVectorComponent(selection->GetComponent());
  return grid;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastMeshInput::ReportBlocks(vtkTetMeshValidationReport* report)
{
  report->SetNumberOfBlocks(this->Composite ? this->Merger->GetNumberOfBlocks() : 0);
  report->SetNumberOfEmptyBlocks(this->Composite ? this->Merger->GetNumberOfEmptyBlocks() : 0);
  report->SetNumberOfSharedPoints(this->Composite ? this->Merger->GetNumberOfSharedPoints() : 0);
}
