/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastMeshInput.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastMeshInput.h"

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
  this->MergedScalars->SetVectorModeToComponent();
}

//------------------------------------------------------------------------------
vtkTiledRayCastMeshInput::~vtkTiledRayCastMeshInput()
{
  this->Merger->Delete();
}

//------------------------------------------------------------------------------
vtkDataSet* vtkTiledRayCastMeshInput::Prepare(vtkTiledRayCastVolumeMapper* mapper,
  vtkDataObject* input, vtkVolumeProperty* property, vtkTetMeshBuilder* builder, std::string& error)
{
  this->Composite = false;
  if (vtkDataObjectTree* tree = vtkDataObjectTree::SafeDownCast(input))
  {
    this->Composite = true;
    vtkTetMeshBlockMerger* merger = this->Merger;
    merger->GetScalarSelection()->CopySettings(mapper->GetScalarSelection());
    vtkUnstructuredGrid* merged = merger->Merge(tree, property);
    if (!merged)
    {
      error = std::string("Cannot render the composite input: ") + merger->GetErrorMessage();
      return nullptr;
    }
    // The merged grid's active scalars are the one scalar to render.
    builder->GetScalarSelection()->CopySettings(this->MergedScalars);
    return merged;
  }

  // The one scalar the property takes from the array (vtkTetScalarSelection's rule, which the
  // reference renderer follows too), resolved here for the builder, which sees no property; a
  // missing array is the builder's error.
  vtkDataSet* grid = vtkDataSet::SafeDownCast(input);
  vtkNew<vtkTetScalarSelection> selection;
  selection->CopySettings(mapper->GetScalarSelection());
  int cellFlag = -1;
  vtkDataArray* array = selection->GetScalars(grid, cellFlag);
  if (array && !selection->Resolve(array->GetNumberOfComponents(), array->GetName(), property))
  {
    error = std::string("Not rendered: ") + selection->GetErrorMessage();
    return nullptr;
  }
  selection->SetVectorModeToResolved();
  builder->GetScalarSelection()->CopySettings(selection);
  return grid;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastMeshInput::ReportBlocks(vtkTetMeshValidationReport* report)
{
  report->SetNumberOfBlocks(this->Composite ? this->Merger->GetNumberOfBlocks() : 0);
  report->SetNumberOfEmptyBlocks(this->Composite ? this->Merger->GetNumberOfEmptyBlocks() : 0);
  report->SetNumberOfSharedPoints(this->Composite ? this->Merger->GetNumberOfSharedPoints() : 0);
}
