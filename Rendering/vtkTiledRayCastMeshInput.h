/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastMeshInput.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastMeshInput
 * @brief   private: the grid the mapper's mesh builder builds, and its scalar selection
 *
 * vtkOpenGLTiledRayCastVolumeMapper's input is a vtkUnstructuredGridBase or a composite data set
 * (vtkDataObjectTree: multiblock, partitioned data sets). Prepare() gives the builder a grid and
 * the settings that select its one scalar: for a grid, the mapper's scalar selection resolved
 * with the volume property (vtkTetScalarSelection); for a composite input, the blocks merged
 * into one grid of one scalar (vtkTetMeshBlockMerger), whose active scalars the builder then
 * takes as they are.
 */

#ifndef vtkTiledRayCastMeshInput_h
#define vtkTiledRayCastMeshInput_h

#include "vtkNew.h"                // For vtkNew
#include "vtkTetScalarSelection.h" // For vtkNew<vtkTetScalarSelection>

#include <string> // For std::string

class vtkDataObject;
class vtkDataSet;
class vtkTetMeshBlockMerger;
class vtkTetMeshBuilder;
class vtkTetMeshValidationReport;
class vtkTiledRayCastVolumeMapper;
class vtkVolumeProperty;

class vtkTiledRayCastMeshInput
{
public:
  vtkTiledRayCastMeshInput();
  ~vtkTiledRayCastMeshInput();

  /**
   * The grid to build from `input` with `builder`, whose scalar selection is set; null with
   * `error` when nothing can be rendered.
   */
  vtkDataSet* Prepare(vtkTiledRayCastVolumeMapper* mapper, vtkDataObject* input,
    vtkVolumeProperty* property, vtkTetMeshBuilder* builder, std::string& error);

  /**
   * Write the composite input's figures (blocks, empty blocks, shared points; zeros for a
   * grid) into `report`.
   */
  void ReportBlocks(vtkTetMeshValidationReport* report);

private:
  vtkTiledRayCastMeshInput(const vtkTiledRayCastMeshInput&) = delete;
  void operator=(const vtkTiledRayCastMeshInput&) = delete;

  vtkTetMeshBlockMerger* Merger;
  // What the builder reads of the merged grid: its active scalars, one component.
  vtkNew<vtkTetScalarSelection> MergedScalars;
  bool Composite = false;
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastMeshInput.h
