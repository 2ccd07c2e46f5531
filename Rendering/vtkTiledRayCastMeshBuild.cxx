/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastMeshBuild.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastMeshBuild.h"

#include "vtkCallbackCommand.h"
#include "vtkDataSet.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkTetMesh.h"
#include "vtkTetMeshBuilder.h"
#include "vtkTetMeshCompactLayout.h"
#include "vtkTetMeshLayout.h"
#include "vtkTetMeshPaperLayout.h"
#include "vtkTetMeshValidationReport.h"
#include "vtkTiledRayCastMemoryBudget.h"
#include "vtkTiledRayCastStatistics.h"
#include "vtkTiledRayCastVolumeMapper.h"
#include "vtkTimerLog.h"

#include <algorithm>
#include <cmath>

//------------------------------------------------------------------------------
vtkTiledRayCastMeshBuild::vtkTiledRayCastMeshBuild(vtkTiledRayCastVolumeMapper* mapper)
  : Mapper(mapper)
{
  // The builder and the layouts are the mapper's own parts: their errors and warnings end
  // up in the validation report and in the mapper's one message about them, so that a user
  // (or a test) hears of a problem once and from the object they hold.
  this->Silencer->SetCallback([](vtkObject*, unsigned long, void*, void*) {});
  this->Builder->AddObserver(vtkCommand::ErrorEvent, this->Silencer);
  this->Builder->AddObserver(vtkCommand::WarningEvent, this->Silencer);
  // The builder's progress is the mapper's (0 to 0.9, packing the layout the rest), so that
  // an application can show it for a mesh that takes seconds to build.
  this->BuildProgress->SetClientData(mapper);
  this->BuildProgress->SetCallback(
    [](vtkObject*, unsigned long, void* m, void* fraction)
    {
      static_cast<vtkTiledRayCastVolumeMapper*>(m)->UpdateProgress(
        0.9 * *static_cast<double*>(fraction));
    });
  this->Builder->AddObserver(vtkCommand::ProgressEvent, this->BuildProgress);
}

//------------------------------------------------------------------------------
vtkTiledRayCastMeshBuild::~vtkTiledRayCastMeshBuild() = default;

//------------------------------------------------------------------------------
vtkTetMesh* vtkTiledRayCastMeshBuild::GetMesh()
{
  return this->Builder->GetMesh();
}

//------------------------------------------------------------------------------
vtkTetMeshLayout* vtkTiledRayCastMeshBuild::GetLayout()
{
  return this->Layout;
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastMeshBuild::Update(vtkDataObject* dataObject, vtkVolumeProperty* property,
  int maxTextureSize, int maxTextureBufferSize, vtkTiledRayCastMemoryBudget& budget,
  std::string& error)
{
  vtkTiledRayCastVolumeMapper* self = this->Mapper;
  vtkTetMeshBuilder* builder = this->Builder;
  builder->SetSpatialOrdering(self->GetSpatialOrdering());
  builder->SetPointOrdering(self->GetSpatialOrdering()); // the points along the same curve
  // A grid, or a composite input merged into one (vtkTiledRayCastMeshInput), with the builder's
  // scalar selection set for it.
  std::string inputError;
  vtkDataSet* input = this->Input.Prepare(self, dataObject, property, builder, inputError);
  if (!input)
  {
    error = inputError + ". Nothing is drawn.";
    return false;
  }

  // What cannot fit on the GPU is refused before it is built, where the input's counts tell;
  // an input found to fit is not checked again until it (or the user's limit) changes.
  const bool paper = self->GetMeshLayout() == vtkTiledRayCastVolumeMapper::PAPER_LAYOUT;
  // Keyed on the topology's arrays, not the input's time: a deforming mesh changes only its points.
  std::vector<vtkTetMeshBuildState::Stamp> topology;
  vtkTetMeshBuildState::GetTopologyStamps(input, topology);
  const bool checkBudget = input != this->BudgetInput || topology != this->BudgetTopology ||
    input->GetNumberOfPoints() != this->BudgetPoints ||
    budget.GetUserLimit() != this->BudgetUserLimit;
  this->BudgetInput = nullptr;
  std::string budgetError;
  if (checkBudget && !budget.CheckInput(input, paper, budgetError))
  {
    error = "Cannot draw the input: " + budgetError + ". Nothing is drawn.";
    return false;
  }

  // The builder rebuilds only what changed (nothing, the scalars, the points, or everything).
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  vtkTetMesh* mesh = builder->Build(input);
  vtkTetMeshValidationReport* report = mesh ? mesh->GetReport() : nullptr;
  if (report)
  {
    this->Input.ReportBlocks(report);
  }
  // A mesh whose every tetrahedron has zero volume holds nothing to integrate: refused, as the
  // reference refuses it (drawn, its flat faces left a few pixels of noise).
  const bool allFlat = report && report->GetNumberOfTetrahedra() > 0 &&
    report->GetNumberOfDegenerateTetrahedra() == report->GetNumberOfTetrahedra();
  if (report && report->GetMTime() > this->ReportedTime)
  {
    self->GetValidationReport()->DeepCopy(report);
    this->ReportedTime = report->GetMTime();
    const bool problems = self->GetWarnAboutDegenerateCells()
      ? report->HasProblems()
      : report->HasProblemsBesidesDegeneracy();
    if (report->GetUsable() && problems && !allFlat)
    {
      vtkWarningWithObjectMacro(self, << "Input mesh: " << report->GetSummary());
    }
  }
  if (!report || !report->GetUsable())
  {
    error = std::string("Cannot render the input: ") +
      (report ? report->GetErrorMessage() : "no mesh") + ". Nothing is drawn.";
    return false;
  }
  if (allFlat)
  {
    error = "Cannot render the input: every one of its " +
      std::to_string(report->GetNumberOfTetrahedra()) +
      " tetrahedra has zero volume (degenerate), so there is nothing to integrate. Nothing is "
      "drawn.";
    return false;
  }

  // The layout the user asked for, within the GPU's limits (or the user's lower ones): repacked
  // only where the mesh changed (only the point texture when only the points moved).
  const int userTexture = self->GetMaximumTextureSize();
  const vtkIdType userBuffer = self->GetMaximumTextureBufferSize();
  const int textureLimit = userTexture > 0 ? std::min(userTexture, maxTextureSize) : maxTextureSize;
  const vtkIdType bufferLimit =
    userBuffer > 0 ? std::min<vtkIdType>(userBuffer, maxTextureBufferSize) : maxTextureBufferSize;
  const int kind = self->GetMeshLayout();
  if (kind != this->LayoutKind || !this->Layout || textureLimit != this->LayoutTextureLimit)
  {
    this->LayoutTextureLimit = textureLimit;
    if (kind == vtkTiledRayCastVolumeMapper::PAPER_LAYOUT)
    {
      // Rows of three texels per tetrahedron: a wide texture keeps the height small.
      vtkNew<vtkTetMeshPaperLayout> paper;
      paper->SetTextureWidth(std::min(textureLimit, 8192));
      this->Layout = paper;
    }
    else
    {
      this->Layout = vtkSmartPointer<vtkTetMeshCompactLayout>::New();
    }
    this->Layout->AddObserver(vtkCommand::ErrorEvent, this->Silencer);
    this->Layout->AddObserver(vtkCommand::WarningEvent, this->Silencer);
    this->LayoutKind = kind;
    this->NewLayout = true;
  }
  vtkTetMeshLayout* layout = this->Layout;
  layout->SetMaximumTextureSize(textureLimit);
  layout->SetMaximumTextureBufferSize(bufferLimit);
  this->TextureBufferLimit = bufferLimit;
  if (!layout->Update(mesh))
  {
    error = std::string("Cannot pack the mesh for this GPU: ") + layout->GetErrorMessage() +
      ". Nothing is drawn.";
    return false;
  }
  // The visible set (a bit per tetrahedron) and the entry faces (a word each) come with it.
  const vtkIdType visibleBytes =
    (mesh->GetNumberOfTetrahedra() + 7) / 8 + 4 * mesh->GetNumberOfBoundaryFaces();
  if ((checkBudget || layout->GetLastUpdate() != vtkTetMeshLayout::UpdatedNothing) &&
    !budget.CheckLayout(layout, visibleBytes, budgetError))
  {
    error = "Cannot draw the input: " + budgetError + ". Nothing is drawn.";
    return false;
  }
  this->BudgetInput = input;
  this->BudgetTopology = topology;
  this->BudgetPoints = input->GetNumberOfPoints();
  this->BudgetUserLimit = budget.GetUserLimit();
  timer->StopTimer();
  self->GetStatistics()->SetMeshBuildTime(timer->GetElapsedTime());
  // The builder's flags are the statistics' (scalars 1, points 2, topology 4).
  self->GetStatistics()->SetMeshRebuild(builder->GetLastRebuild());
  if (builder->GetLastRebuild() != vtkTetMeshBuilder::RebuildNothing)
  {
    self->UpdateProgress(1.0);
  }

  if (mesh->GetMTime() != this->MeshTime)
  {
    this->MeshTime = mesh->GetMTime();
    this->NumberOfTets = mesh->GetNumberOfTetrahedra();
    this->HasCellScalars = mesh->GetHasCellScalars();
    double bounds[6], shift[3];
    mesh->GetBounds(bounds);
    mesh->GetShift(shift);
    mesh->GetScalarRange(this->ScalarRange);
    this->LongestEdge = mesh->GetLongestEdge();
    this->SetFrameValues(bounds, shift);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastMeshBuild::SetFrameValues(const double bounds[6], const double shift[3])
{
  std::copy(shift, shift + 3, this->Shift);
  for (int i = 0; i < 6; ++i)
  {
    this->MeshBounds[i] = bounds[i] - this->Shift[i / 2];
  }
  const double volume = (bounds[1] - bounds[0]) * (bounds[3] - bounds[2]) * (bounds[5] - bounds[4]);
  // The edge of a regular tetrahedron of the mean volume: a typical segment length.
  this->TypicalEdge =
    this->NumberOfTets > 0 ? std::cbrt(6.0 * std::sqrt(2.0) * volume / this->NumberOfTets) : 0.0;
}

//------------------------------------------------------------------------------
vtkPointSet* vtkTiledRayCastMeshBuild::GetMovedPointsOnly(vtkDataObject* dataObject,
  vtkVolumeProperty* property, int maxTextureSize, int maxTextureBufferSize,
  const vtkTiledRayCastMemoryBudget& budget)
{
  vtkTiledRayCastVolumeMapper* self = this->Mapper;
  vtkTetMeshBuilder* builder = this->Builder;
  vtkTetMesh* mesh = builder->GetMesh();
  // The layout and limits Update() would use now must be those of the last Update().
  const int userTexture = self->GetMaximumTextureSize();
  const vtkIdType userBuffer = self->GetMaximumTextureBufferSize();
  const int textureLimit = userTexture > 0 ? std::min(userTexture, maxTextureSize) : maxTextureSize;
  const vtkIdType bufferLimit =
    userBuffer > 0 ? std::min<vtkIdType>(userBuffer, maxTextureBufferSize) : maxTextureBufferSize;
  if (!this->Layout || !this->Layout->GetValid() ||
    self->GetMeshLayout() != vtkTiledRayCastVolumeMapper::COMPACT_LAYOUT ||
    this->LayoutKind != vtkTiledRayCastVolumeMapper::COMPACT_LAYOUT ||
    textureLimit != this->LayoutTextureLimit || bufferLimit != this->TextureBufferLimit ||
    budget.GetUserLimit() != this->BudgetUserLimit || !mesh || !mesh->GetReport()->GetUsable() ||
    builder->GetSpatialOrdering() != self->GetSpatialOrdering())
  {
    return nullptr;
  }
  // A composite input is merged into a new grid by Update() (not before it: merging is the
  // cost this path avoids).
  if (!vtkPointSet::SafeDownCast(dataObject))
  {
    return nullptr;
  }
  std::string error;
  vtkPointSet* input =
    vtkPointSet::SafeDownCast(this->Input.Prepare(self, dataObject, property, builder, error));
  if (!input || input != this->BudgetInput || !input->GetPoints() ||
    builder->GetPendingRebuild(input) != vtkTetMeshBuilder::RebuildPoints)
  {
    return nullptr;
  }
  return input;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastMeshBuild::ShiftOf(vtkPointSet* input, double shift[3])
{
  // The centre of the bounds, as the builder shifts a mesh (vtkTetMeshCellExtraction).
  const double* bounds = input->GetPoints()->GetBounds();
  for (int c = 0; c < 3; ++c)
  {
    shift[c] = 0.5 * (bounds[2 * c] + bounds[2 * c + 1]);
  }
}

//------------------------------------------------------------------------------
void vtkTiledRayCastMeshBuild::MovedPoints(vtkPointSet* input, double longestEdge, double seconds)
{
  double shift[3];
  ShiftOf(input, shift);
  this->LongestEdge = longestEdge;
  this->SetFrameValues(input->GetPoints()->GetBounds(), shift);
  vtkTiledRayCastStatistics* stats = this->Mapper->GetStatistics();
  stats->SetMeshBuildTime(seconds);
  stats->SetMeshRebuild(vtkTiledRayCastStatistics::MeshRebuildPointsOnGPU);
}

//------------------------------------------------------------------------------
double vtkTiledRayCastMeshBuild::GetDegeneracyTolerance() const
{
  return this->Builder->GetDegeneracyTolerance();
}
