/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshBuilder.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetMeshBuilder.h"

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkTetMesh.h"
#include "vtkTetMeshBuildState.h"
#include "vtkTetMeshCellExtraction.h"
#include "vtkTetMeshDefectSearch.h"
#include "vtkTetMeshFaceMatching.h"
#include "vtkTetMeshOrientation.h"
#include "vtkTetMeshScalarExtraction.h"
#include "vtkTetMeshSpatialOrder.h"
#include "vtkTetMeshValidationReport.h"
#include "vtkTimerLog.h"

#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkTetMeshBuilder);

namespace
{
constexpr uint32_t NoNeighbor = vtkTetMesh::NoNeighbor;
// Neighbour words keep 2 bits for the face: a mesh holds at most 2^30 tetrahedra.
constexpr vtkIdType MaxTetrahedra = vtkIdType(1) << 30;
using ScopedEvent = vtkTetMeshBuildState::ScopedEvent;
using Stamp = vtkTetMeshBuildState::Stamp;

//------------------------------------------------------------------------------
// Build() reports its progress as vtkAlgorithm::UpdateProgress does: a ProgressEvent whose call
// data is a double* fraction in [0, 1]. The fractions reached after each phase of a full build
// follow the time each phase takes (docs/mesh-layout.md, post_tets6 and bracket): reading the
// points and cells 10 %, orientation 20 %, face matching 55 %, duplicates and cracks 10 %,
// scalars the rest.
void ReportProgress(vtkObject* builder, double fraction)
{
  builder->InvokeEvent(vtkCommand::ProgressEvent, &fraction);
}
}

//------------------------------------------------------------------------------
vtkTetMeshBuilder::vtkTetMeshBuilder()
  : State(new vtkTetMeshBuildState)
{
  // The builder sees no volume property: what it reads is a component or the magnitude, as a
  // mapper resolved it (vtkTetScalarSelection::SetVectorModeToResolved()).
  this->ScalarSelection->SetVectorModeToComponent();
}

//------------------------------------------------------------------------------
vtkTetMeshBuilder::~vtkTetMeshBuilder() = default;

//------------------------------------------------------------------------------
vtkTetMesh* vtkTetMeshBuilder::GetMesh()
{
  return this->State->Mesh;
}

//------------------------------------------------------------------------------
void vtkTetMeshBuilder::Invalidate()
{
  this->State->Valid = false;
}

//------------------------------------------------------------------------------
void vtkTetMeshBuilder::ReleaseScratchMemory()
{
  this->State->ReleaseScratch();
}

//------------------------------------------------------------------------------
vtkIdType vtkTetMeshBuilder::GetScratchMemorySize()
{
  return this->State->GetScratchSize();
}

//------------------------------------------------------------------------------
const char* vtkTetMeshBuilder::GetRebuildAsString(int rebuild)
{
  switch (rebuild & RebuildAll)
  {
    case RebuildNothing:
      return "nothing";
    case RebuildScalars:
      return "scalars";
    case RebuildPoints:
      return "points";
    case RebuildPoints | RebuildScalars:
      return "points and scalars";
    default:
      return "all";
  }
}

//------------------------------------------------------------------------------
int vtkTetMeshBuilder::GetPendingRebuild(vtkDataSet* input)
{
  const vtkTetMeshBuildState& state = *this->State;
  std::vector<Stamp> topology;
  vtkTetMeshBuildState::GetTopologyStamps(input, topology);
  const bool full = !state.Valid || state.Input != input || state.TopologyStamps != topology ||
    state.NumberOfPoints != (input ? input->GetNumberOfPoints() : -1) ||
    state.SpatialOrdering != this->SpatialOrdering || state.PointOrdering != this->PointOrdering ||
    state.DegeneracyTolerance != this->DegeneracyTolerance;
  if (full)
  {
    return RebuildAll;
  }
  int cellFlag = -1;
  vtkDataArray* scalars = this->ScalarSelection->GetScalars(input, cellFlag);
  const bool pointsChanged = state.PointsStamp != vtkTetMeshBuildState::GetPointsStamp(input);
  const bool scalarsChanged = state.ScalarsStamp != vtkTetMeshBuildState::MakeStamp(scalars) ||
    state.ScalarsCellFlag != (scalars ? cellFlag : -1) ||
    !state.ScalarSettings->HasSameSettings(this->ScalarSelection);
  return (pointsChanged ? RebuildPoints : RebuildNothing) |
    (scalarsChanged ? RebuildScalars : RebuildNothing);
}

//------------------------------------------------------------------------------
vtkTetMesh* vtkTetMeshBuilder::Build(vtkDataSet* input)
{
  const double start = vtkTimerLog::GetUniversalTime();
  vtkTetMeshBuildState& state = *this->State;
  vtkTetMesh* mesh = state.Mesh;
  this->LastRebuild = RebuildNothing;

  // What changed since the last build?
  const int pending = this->GetPendingRebuild(input);
  const bool full = (pending & RebuildTopology) != 0;
  const bool pointsChanged = (pending & RebuildPoints) != 0;
  bool scalarsChanged = (pending & RebuildScalars) != 0;
  if (pending == RebuildNothing)
  {
    this->LastBuildTime = vtkTimerLog::GetUniversalTime() - start;
    return mesh;
  }
  std::vector<Stamp> topology;
  vtkTetMeshBuildState::GetTopologyStamps(input, topology);
  const Stamp pointsStamp = vtkTetMeshBuildState::GetPointsStamp(input);
  int cellFlag = -1;
  vtkDataArray* scalars = this->ScalarSelection->GetScalars(input, cellFlag);

  ReportProgress(this, 0.0);
  bool doFull = full;
  if (!doFull && pointsChanged)
  {
    doFull = !this->UpdatePoints(input);
    state.PointsStamp = pointsStamp;
  }
  if (doFull)
  {
    this->BuildTopology(input);
    state.Input = input;
    state.TopologyStamps = topology;
    state.PointsStamp = pointsStamp;
    state.NumberOfPoints = input ? input->GetNumberOfPoints() : -1;
    state.SpatialOrdering = this->SpatialOrdering;
    state.PointOrdering = this->PointOrdering;
    state.DegeneracyTolerance = this->DegeneracyTolerance;
    state.Valid = true;
    scalarsChanged = true;
  }
  if (scalarsChanged)
  {
    this->UpdateScalars(input);
    // ReadScalars records the array it used; keep the one the change test sees otherwise.
    if (!state.TopologyError.empty() || !state.ScalarError.empty())
    {
      state.ScalarsStamp = vtkTetMeshBuildState::MakeStamp(scalars);
      state.ScalarsCellFlag = scalars ? cellFlag : -1;
    }
  }

  this->FinishReport(input);
  mesh->Modified();
  this->LastBuildTime = vtkTimerLog::GetUniversalTime() - start;
  ReportProgress(this, 1.0);
  return mesh;
}

//------------------------------------------------------------------------------
// Deforming mesh: new positions, same tetrahedra. False when that is not enough (a tetrahedron
// turned inside out, or the last build had failed): a full build must follow.
bool vtkTetMeshBuilder::UpdatePoints(vtkDataSet* input)
{
  vtkTetMeshBuildState& state = *this->State;
  vtkTetMesh* mesh = state.Mesh;
  std::string error;
  ScopedEvent event("vtkTetMeshBuilder: points only");
  if (!vtkTetMeshCellExtraction::ReadPoints(state, input, error))
  {
    state.TopologyError = error;
    // Initialize() empties the report too, yet the counters of the last full build stand (as
    // on any points-only build): keep them across.
    vtkNew<vtkTetMeshValidationReport> kept;
    kept->DeepCopy(state.GetReport());
    mesh->Initialize();
    state.GetReport()->DeepCopy(kept);
    this->LastRebuild = RebuildAll;
    vtkErrorMacro(<< "Cannot build a tetrahedral mesh: " << error << ".");
    return true;
  }
  vtkTetMeshSpatialOrder::ApplyPointOrder(mesh, mesh->Points, 3); // the last full build's order
  if (!state.TopologyError.empty() ||
    !vtkTetMeshOrientation::Classify(state, this->DegeneracyTolerance, false))
  {
    return false;
  }
  this->LastRebuild |= RebuildPoints;
  mesh->PointsTime.Modified();
  return true;
}

//------------------------------------------------------------------------------
// Everything from the input: the mesh and its report start empty, each stage fills its part.
void vtkTetMeshBuilder::BuildTopology(vtkDataSet* input)
{
  vtkTetMeshBuildState& state = *this->State;
  vtkTetMesh* mesh = state.Mesh;
  this->LastRebuild = RebuildAll;
  state.Valid = false;
  state.TopologyError.clear();
  state.ScalarError.clear();
  mesh->Initialize(); // the report too: every counter starts at 0
  state.GetReport()->SetNumberOfInputCells(input ? input->GetNumberOfCells() : 0);

  std::string error;
  if (this->ExtractCells(input, error))
  {
    this->RunTopologyStages();
  }
  else
  {
    state.TopologyError = error;
    mesh->TetPoints.clear();
    mesh->TetInputCellIds.clear();
    vtkErrorMacro(<< "Cannot build a tetrahedral mesh: " << error << ".");
  }
  mesh->TopologyTime.Modified();
  mesh->PointsTime.Modified();
}

//------------------------------------------------------------------------------
// The points and tetrahedra of a usable input; false (and `error`) for any other.
bool vtkTetMeshBuilder::ExtractCells(vtkDataSet* input, std::string& error)
{
  vtkTetMeshBuildState& state = *this->State;
  if (!input)
  {
    error = "no input";
    return false;
  }
  if (input->GetNumberOfPoints() == 0 || input->GetNumberOfCells() == 0)
  {
    error = "the grid is empty";
    return false;
  }
  if (input->GetNumberOfPoints() >= static_cast<vtkIdType>(NoNeighbor) ||
    input->GetNumberOfCells() >= static_cast<vtkIdType>(NoNeighbor))
  {
    error = "the grid has too many points or cells (at most 2^32 - 1 of each)";
    return false;
  }
  bool ok;
  {
    ScopedEvent event("vtkTetMeshBuilder: points");
    ok = vtkTetMeshCellExtraction::ReadPoints(state, input, error);
  }
  if (ok)
  {
    ScopedEvent event("vtkTetMeshBuilder: cells");
    ok = vtkTetMeshCellExtraction::ExtractTetrahedra(state, input, error);
  }
  ReportProgress(this, 0.1);
  if (!ok)
  {
    return false;
  }
  const vtkIdType numTets = state.Mesh->GetNumberOfTetrahedra();
  vtkTetMeshValidationReport* report = state.GetReport();
  std::ostringstream text;
  if (numTets == 0)
  {
    text << "the grid has no 3D cells (" << report->GetNumberOfIgnoredCells()
         << " cells of lower dimension";
    if (report->GetNumberOfInvalidCells() > 0)
    {
      text << ", " << report->GetNumberOfInvalidCells() << " invalid cells";
    }
    text << ")";
  }
  else if (numTets > MaxTetrahedra)
  {
    text << "the grid gives " << numTets << " tetrahedra, more than the 2^30 a mesh can hold";
  }
  error = text.str();
  return error.empty();
}

//------------------------------------------------------------------------------
// The stages after extraction, in order. Each is a vtkTimerLog event (recorded when
// vtkTimerLog::LoggingOn()): the benchmark prints them, face matching being the part that grows
// fastest.
void vtkTetMeshBuilder::RunTopologyStages()
{
  vtkTetMeshBuildState& state = *this->State;
  vtkTetMeshValidationReport* report = state.GetReport();
  // Splitting non-tetrahedral cells (and reorienting inverted tetrahedra) is normal service:
  // the report counts them, and only what the builder could not use is warned about.
  if (report->GetNumberOfIgnoredCells() > 0 || report->GetNumberOfInvalidCells() > 0)
  {
    vtkWarningMacro(<< "Ignored " << report->GetNumberOfIgnoredCells()
                    << " cells of dimension lower than 3 (or of unsupported types) and "
                    << report->GetNumberOfInvalidCells() << " invalid cells (bad point ids).");
  }
  // Scratch beyond MaximumKeptScratchMemory goes when its stage ends.
  auto trimScratch = [&]()
  {
    if (state.GetScratchSize() > this->MaximumKeptScratchMemory)
    {
      state.ReleaseScratch();
    }
  };
  if (this->SpatialOrdering)
  {
    ScopedEvent event("vtkTetMeshBuilder: spatial sort");
    vtkTetMeshSpatialOrder::Sort(state);
    trimScratch();
  }
  if (this->PointOrdering)
  {
    ScopedEvent event("vtkTetMeshBuilder: point order");
    vtkTetMeshSpatialOrder::SortPoints(state);
    trimScratch();
  }
  {
    ScopedEvent event("vtkTetMeshBuilder: orientation");
    vtkTetMeshOrientation::Classify(state, this->DegeneracyTolerance, true);
  }
  ReportProgress(this, 0.3);
  {
    ScopedEvent event("vtkTetMeshBuilder: face matching");
    // A huge mesh's passes report their progress between 0.3 and 0.8.
    vtkTetMeshFaceMatching::MatchFaces(state, this->MaximumKeptScratchMemory,
      [this](double done) { ReportProgress(this, 0.3 + 0.5 * done); });
    vtkTetMeshOrientation::OrientDegenerate(state);
    vtkTetMeshFaceMatching::CollectBoundaryFaces(state);
    trimScratch();
  }
  ReportProgress(this, 0.85);
  {
    ScopedEvent event("vtkTetMeshBuilder: duplicates and cracks");
    vtkTetMeshDefectSearch::FindDuplicatesAndCracks(state);
    trimScratch();
  }
  ReportProgress(this, 0.95);
}

//------------------------------------------------------------------------------
// The scalars, read anew (unless the topology is unusable), and the settings they were read
// with.
void vtkTetMeshBuilder::UpdateScalars(vtkDataSet* input)
{
  vtkTetMeshBuildState& state = *this->State;
  state.ScalarError.clear();
  if (state.TopologyError.empty())
  {
    ScopedEvent event("vtkTetMeshBuilder: scalars");
    std::string error;
    if (!vtkTetMeshScalarExtraction::ReadScalars(state, input, this->ScalarSelection, error))
    {
      state.ScalarError = error;
      vtkErrorMacro(<< "Cannot render the grid: " << error << ".");
    }
    vtkTetMeshScalarExtraction::FlagNonFiniteTets(state);
  }
  state.ScalarSettings->CopySettings(this->ScalarSelection);
  this->LastRebuild |= RebuildScalars;
  state.Mesh->ScalarsTime.Modified();
}

//------------------------------------------------------------------------------
// The stages wrote their counters into the report as they ran (a partial rebuild keeps those
// of the stages it did not run); what is left is the mesh's size and the error.
void vtkTetMeshBuilder::FinishReport(vtkDataSet* input)
{
  vtkTetMeshBuildState& state = *this->State;
  vtkTetMesh* mesh = state.Mesh;
  vtkTetMeshValidationReport* report = state.GetReport();
  report->SetNumberOfInputPoints(input ? input->GetNumberOfPoints() : 0);
  report->SetNumberOfTetrahedra(mesh->GetNumberOfTetrahedra());
  report->SetNumberOfBoundaryFaces(mesh->GetNumberOfBoundaryFaces());
  // The block counts are not the builder's: whoever merged the blocks writes them afterwards.
  report->SetNumberOfBlocks(0);
  report->SetNumberOfEmptyBlocks(0);
  report->SetNumberOfSharedPoints(0);
  if (!state.TopologyError.empty())
  {
    report->SetError(state.TopologyError);
  }
  else if (!state.ScalarError.empty())
  {
    report->SetError(state.ScalarError);
  }
  else
  {
    report->ClearError();
  }
  report->Modified();
}

//------------------------------------------------------------------------------
void vtkTetMeshBuilder::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ScalarSelection:\n";
  this->ScalarSelection->PrintSelf(os, indent.GetNextIndent());
  os << indent << "SpatialOrdering: " << (this->SpatialOrdering ? "On" : "Off") << "\n";
  os << indent << "PointOrdering: " << (this->PointOrdering ? "On" : "Off") << "\n";
  os << indent << "DegeneracyTolerance: " << this->DegeneracyTolerance << "\n";
  os << indent << "MaximumKeptScratchMemory: " << this->MaximumKeptScratchMemory << "\n";
  os << indent << "LastRebuild: " << GetRebuildAsString(this->LastRebuild) << "\n";
  os << indent << "LastBuildTime: " << this->LastBuildTime << "\n";
  os << indent << "Mesh: " << this->State->Mesh.GetPointer() << "\n";
}
