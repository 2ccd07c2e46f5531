/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTiledRayCastComposite.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Composite input (vtkTetMeshBlockMerger): a block of tetrahedra cut in two unstructured grids
// (interface points duplicated, each block with its own arrays, the scalars selected by name),
// rendered as a vtkMultiBlockDataSet given with SetInputData, through a pipeline
// (vtkMultiBlockDataGroupFilter -> SetInputConnection, the camera reset from the mapper's
// bounds), as a vtkPartitionedDataSetCollection, with empty and null blocks, with scalars that
// jump across the interface (no shared points: crack faces) and with cell scalars. Each image is
// compared with the exact reference rendering the blocks appended into one grid by VTK
// (vtkAppendFilter, points not merged). A block of image data is refused with an error and
// nothing drawn. Before: every composite input was refused by the pipeline (vtkUnstructuredGridBase
// required).
#include "TiledRayCastTestGrids.h"
#include "TiledRayCastTestScene.h"

#include "vtkAppendFilter.h"
#include "vtkCellData.h"
#include "vtkCellTypeSource.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkMultiBlockDataGroupFilter.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPartitionedDataSet.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTetMeshValidationReport.h"

#include <functional>
#include <vector>

namespace
{
using trctest::Expect;
using trctest::MessageCounter;

// A 4x4x4 block of tetrahedra over [0, 4]^3 cut at x = 2 into two grids; point scalars
// "s" = x + 2y + 3z (+ `jump` in the second block), after an unrelated array in the second block
// so that the scalars are found by name, not by index.
void TwoBlocks(double jump, vtkSmartPointer<vtkUnstructuredGrid> blocks[2])
{
  vtkNew<vtkCellTypeSource> source;
  source->SetCellType(VTK_TETRA);
  source->SetBlocksDimensions(4, 4, 4);
  source->Update();
  vtkUnstructuredGrid* whole = source->GetOutput();
  vtkNew<vtkIdList> cells[2];
  for (vtkIdType c = 0; c < whole->GetNumberOfCells(); ++c)
  {
    double bounds[6];
    whole->GetCellBounds(c, bounds);
    cells[bounds[0] + bounds[1] < 4.0 ? 0 : 1]->InsertNextId(c);
  }
  for (int b = 0; b < 2; ++b)
  {
    // The cells of the half, with their own points (the interface points in both halves).
    blocks[b] = vtkSmartPointer<vtkUnstructuredGrid>::New();
    vtkNew<vtkPoints> points;
    std::vector<vtkIdType> map(whole->GetNumberOfPoints(), -1);
    for (vtkIdType k = 0; k < cells[b]->GetNumberOfIds(); ++k)
    {
      vtkNew<vtkIdList> ids;
      whole->GetCellPoints(cells[b]->GetId(k), ids);
      for (vtkIdType j = 0; j < ids->GetNumberOfIds(); ++j)
      {
        vtkIdType& id = map[ids->GetId(j)];
        if (id < 0)
        {
          id = points->InsertNextPoint(whole->GetPoint(ids->GetId(j)));
        }
        ids->SetId(j, id);
      }
      blocks[b]->InsertNextCell(VTK_TETRA, ids);
    }
    blocks[b]->SetPoints(points);
    if (b == 1)
    {
      vtkNew<vtkDoubleArray> other;
      other->SetName("other");
      other->SetNumberOfTuples(blocks[b]->GetNumberOfPoints());
      other->FillValue(7.0);
      blocks[b]->GetPointData()->AddArray(other);
    }
    blocks[b]->GetPointData()->AddArray(
      trctest::LinearScalars(blocks[b], "s", b == 1 ? jump : 0.0));
  }
}

// The blocks appended by VTK, points not merged: what the reference renders.
vtkSmartPointer<vtkUnstructuredGrid> Appended(vtkSmartPointer<vtkUnstructuredGrid> blocks[2])
{
  vtkNew<vtkAppendFilter> append;
  append->MergePointsOff();
  append->AddInputData(blocks[0]);
  append->AddInputData(blocks[1]);
  append->Update();
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->ShallowCopy(append->GetOutput());
  return grid;
}

// A mapper set up by `connect` (input and scalar selection), in a window; renders two views and
// compares each with the reference of `reference`. Checks the block counts of the report.
bool Check(const std::string& label, vtkUnstructuredGrid* reference,
  const std::function<void(vtkTiledRayCastVolumeMapper*)>& connect, vtkIdType blocks,
  vtkIdType empty, bool shared)
{
  trctest::WatchedVolume view(trctest::MakeProperty(0, 24, 2.0), 90);
  connect(view.Mapper);
  MessageCounter* errors = view.CountErrors();
  bool ok = true;
  const double views[2][2] = { { 30, 20 }, { 100, -35 } };
  for (int v = 0; v < 2; ++v)
  {
    trctest::LookFrom(view.Renderer->GetActiveCamera(), views[v][0], views[v][1]);
    view.Renderer->ResetCamera(); // from the mapper's bounds: the composite input's
    view.Window->Render();
    const std::string name = label + ", view " + std::to_string(v);
    ok = Expect(errors->Count == 0, name + ": no error (" + errors->Text + ")") && ok;
    ok = Expect(view.Mapper->GetStatistics()->GetRendered(), name + ": rendered") && ok;
    ok = trctest::CheckAgainstReference(view.Window, view.Renderer, view.Volume, trctest::Bounds(),
           name.c_str(), [reference](vtkTetReferenceRenderer* r) { r->SetInputData(reference); }) &&
      ok;
  }
  vtkTetMeshValidationReport* report = view.Mapper->GetValidationReport();
  std::cout << label << ": " << report->GetSummary() << "\n";
  ok = Expect(report->GetNumberOfBlocks() == blocks && report->GetNumberOfEmptyBlocks() == empty,
         label + ": blocks counted") &&
    ok;
  ok = Expect((report->GetNumberOfSharedPoints() > 0) == shared, label + ": shared points") && ok;
  ok = Expect((report->GetNumberOfCrackFaces() == 0) == shared,
         label + ": crack faces only where the scalars jump") &&
    ok;
  return ok;
}

// Points selected by name, as for each block.
void ByName(vtkTiledRayCastVolumeMapper* mapper, const char* name, bool cells = false)
{
  if (cells)
  {
    mapper->SetScalarModeToUseCellFieldData();
  }
  else
  {
    mapper->SetScalarModeToUsePointFieldData();
  }
  mapper->SelectScalarArray(name);
}

// The mapper's input `input`, its scalars "s" selected by name (ByName).
std::function<void(vtkTiledRayCastVolumeMapper*)> InputByName(
  vtkDataObjectTree* input, bool cells = false)
{
  return [input, cells](vtkTiledRayCastVolumeMapper* m)
  {
    m->SetInputData(input);
    ByName(m, "s", cells);
  };
}
}

int TestTiledRayCastComposite(int, char*[])
{
  bool ok = true;
  vtkSmartPointer<vtkUnstructuredGrid> blocks[2];
  TwoBlocks(0.0, blocks);
  auto appended = Appended(blocks);

  vtkNew<vtkMultiBlockDataSet> multiblock;
  multiblock->SetNumberOfBlocks(2);
  multiblock->SetBlock(0, blocks[0]);
  multiblock->SetBlock(1, blocks[1]);
  ok = Check("multiblock", appended, InputByName(multiblock), 2, 0, true) && ok;

  // Through a pipeline: what a reader's output port gives.
  vtkNew<vtkMultiBlockDataGroupFilter> group;
  group->AddInputData(blocks[0]);
  group->AddInputData(blocks[1]);
  ok = Check(
         "pipeline", appended,
         [&](vtkTiledRayCastVolumeMapper* m)
         {
           m->SetInputConnection(group->GetOutputPort());
           ByName(m, "s");
         },
         2, 0, true) &&
    ok;

  // Partitions, with an empty grid and a null partition.
  vtkNew<vtkPartitionedDataSet> partitions;
  partitions->SetPartition(0, blocks[0]);
  vtkNew<vtkUnstructuredGrid> empty;
  partitions->SetPartition(1, empty);
  partitions->SetPartition(2, nullptr);
  partitions->SetPartition(3, blocks[1]);
  vtkNew<vtkPartitionedDataSetCollection> collection;
  collection->SetPartitionedDataSet(0, partitions);
  ok = Check("partitioned collection with empty blocks", appended, InputByName(collection), 4, 2,
         true) &&
    ok;

  // Scalars that jump across the interface: its points stay distinct (crack faces).
  vtkSmartPointer<vtkUnstructuredGrid> jumping[2];
  TwoBlocks(3.0, jumping);
  vtkNew<vtkMultiBlockDataSet> jumpBlocks;
  jumpBlocks->SetBlock(0, jumping[0]);
  jumpBlocks->SetBlock(1, jumping[1]);
  ok = Check("scalars jumping across blocks", Appended(jumping), InputByName(jumpBlocks), 2, 0,
         false) &&
    ok;

  // Cell scalars, per block.
  vtkSmartPointer<vtkUnstructuredGrid> cellBlocks[2];
  vtkNew<vtkMultiBlockDataSet> cellTree;
  for (int b = 0; b < 2; ++b)
  {
    cellBlocks[b] = trctest::WithCellScalars(blocks[b]);
    cellTree->SetBlock(b, cellBlocks[b]);
  }
  ok = Check("cell scalars", Appended(cellBlocks), InputByName(cellTree, true), 2, 0, true) && ok;

  // A block that is not an unstructured grid: an error, nothing drawn.
  {
    vtkNew<vtkImageData> image;
    image->SetDimensions(3, 3, 3);
    vtkNew<vtkMultiBlockDataSet> mixed;
    mixed->SetBlock(0, blocks[0]);
    mixed->SetBlock(1, image);
    trctest::WatchedVolume view(trctest::MakeProperty(0, 24, 2.0), 40);
    view.Mapper->SetInputData(mixed);
    ByName(view.Mapper, "s");
    MessageCounter* errors = view.CountErrors();
    view.Renderer->ResetCamera();
    view.Window->Render();
    view.Window->Render();
    ok = Expect(errors->Count == 1, "image block: one error (got " + errors->Text + ")") && ok;
    ok = Expect(errors->Text.find("block 1 is a vtkImageData") != std::string::npos,
           "image block: the error names it") &&
      ok;
    ok = Expect(!view.Mapper->GetStatistics()->GetRendered(), "image block: nothing drawn") && ok;
    std::cout << "image block: " << errors->Text << "\n";
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
