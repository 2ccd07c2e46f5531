/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastIntegration.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastIntegration.h"

#include "vtkTetMesh.h"
#include "vtkTiledRayCastPreIntegrationTable.h"
#include "vtkTiledRayCastStatistics.h"
#include "vtkTiledRayCastTransferFunction.h"
#include "vtkTimerLog.h"
#include "vtkVolumeMapper.h"

#include <algorithm>
#include <cmath>

namespace
{
// x rounded (by `round`: std::ceil or std::round) to a power of 2^(1/8).
double Quantized(double x, double (*round)(double))
{
  return x > 0 ? std::exp2(round(8.0 * std::log2(x)) / 8.0) : x;
}
}

//------------------------------------------------------------------------------
vtkTiledRayCastIntegration::vtkTiledRayCastIntegration()
  : Table(vtkSmartPointer<vtkTiledRayCastPreIntegrationTable>::New())
{
}

//------------------------------------------------------------------------------
vtkTiledRayCastIntegration::~vtkTiledRayCastIntegration() = default;

//------------------------------------------------------------------------------
int vtkTiledRayCastIntegration::GetMode(vtkTiledRayCastVolumeMapper* mapper) const
{
  if (mapper->GetBlendMode() != vtkVolumeMapper::COMPOSITE_BLEND)
  {
    return vtkTiledRayCastVolumeMapper::PARTIAL_PRE_INTEGRATION;
  }
  const int mode = mapper->GetIntegrationMode();
  if (mode != vtkTiledRayCastVolumeMapper::AUTOMATIC_INTEGRATION)
  {
    return this->TableTooCoarse ? vtkTiledRayCastVolumeMapper::PARTIAL_PRE_INTEGRATION : mode;
  }
  return this->ForcePartial ? vtkTiledRayCastVolumeMapper::PARTIAL_PRE_INTEGRATION
                            : this->AutomaticMode;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastIntegration::SetUniforms(
  vtkShaderProgram* p, int mode, double scalarShift, double scalarScale)
{
  this->Textures.SetUniforms(
    p, mode, this->TransferFunction, this->Table, scalarShift, scalarScale);
}

//------------------------------------------------------------------------------
void vtkTiledRayCastIntegration::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Textures.ReleaseGraphicsResources(window);
  this->Bytes = 0;
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastIntegration::Update(
  const Frame& frame, vtkVolumeProperty* property, std::string& error)
{
  vtkTiledRayCastVolumeMapper* self = frame.Mapper;
  vtkOpenGLRenderWindow* window = frame.Window;
  vtkTiledRayCastStatistics* stats = self->GetStatistics();
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  this->TransferFunction->Update(property, frame.ScalarRange);
  if (self->GetIntegrationMode() == vtkTiledRayCastVolumeMapper::AUTOMATIC_INTEGRATION &&
    self->GetBlendMode() == vtkVolumeMapper::COMPOSITE_BLEND)
  {
    this->ChooseIntegration(frame, property);
  }

  this->UpdateExplicitTable(frame, property);
  vtkIdType uploaded = 0;
  const int mode = this->GetMode(self);
  stats->SetIntegrationMode(mode);
  stats->SetPredictedError(
    self->GetIntegrationMode() == vtkTiledRayCastVolumeMapper::AUTOMATIC_INTEGRATION
      ? (mode == vtkTiledRayCastVolumeMapper::PARTIAL_PRE_INTEGRATION ? 0.0 : this->PredictedError)
      : -1.0);
  if (mode == vtkTiledRayCastVolumeMapper::PARTIAL_PRE_INTEGRATION)
  {
    this->Textures.UpdateNodes(window, this->TransferFunction, uploaded);
    this->Bytes = static_cast<vtkIdType>(
      this->TransferFunction->GetNodeTexels().size() * sizeof(float) + 512 * 512 * 4);
    stats->SetPreIntegrationTableSize(0, 0, 0);
  }
  else
  {
    // A table of the whole transfer function, at the resolution it needs, within the GPU's
    // limits; rebuilt only when the transfer function, the lengths or the mode changed.
    vtkTiledRayCastPreIntegrationTable* table = this->Table;
    if (!this->Textures.UpdateTable(window, table, mode, uploaded, error))
    {
      return false;
    }
    this->Bytes = table->GetNumberOfBytes();
    int size[3];
    table->GetSize(size);
    stats->SetPreIntegrationTableSize(size);
  }
  timer->StopTimer();
  stats->SetTransferFunctionBuildTime(timer->GetElapsedTime());
  stats->SetNumberOfTransferFunctionNodes(this->TransferFunction->GetNumberOfNodes());
  stats->SetUploadedBytes(stats->GetUploadedBytes() + uploaded);
  return true;
}

//------------------------------------------------------------------------------
// An explicit table mode's table (the automatic mode's comes with its choice), and whether the
// budget cut it: then partial pre-integration draws instead, and the mapper says so once per
// table configuration.
void vtkTiledRayCastIntegration::UpdateExplicitTable(
  const Frame& frame, vtkVolumeProperty* property)
{
  vtkTiledRayCastVolumeMapper* self = frame.Mapper;
  const int requested = self->GetIntegrationMode();
  this->TableTooCoarse = false;
  if (self->GetBlendMode() != vtkVolumeMapper::COMPOSITE_BLEND ||
    (requested != vtkTiledRayCastVolumeMapper::PRE_INTEGRATION_2D &&
      requested != vtkTiledRayCastVolumeMapper::PRE_INTEGRATION_3D))
  {
    return;
  }
  vtkTiledRayCastPreIntegrationTable* table = this->Table;
  vtkTiledRayCastAutomaticIntegration::Configure(
    table, this->TableSettings(frame, false), requested);
  table->Update(property, this->TransferFunction, frame.ScalarRange);
  const int reducedFrom = table->GetReducedFromScalarSize();
  this->TableTooCoarse = reducedFrom > 0;
  if (!this->TableTooCoarse || this->WarnedTooCoarseTable == table->GetMTime())
  {
    return;
  }
  this->WarnedTooCoarseTable = table->GetMTime();
  int size[3];
  table->GetSize(size);
  vtkWarningWithObjectMacro(self, << "The " << table->GetDimension()
                                  << "D pre-integration table of this transfer function would "
                                     "take more than "
                                  << table->GetBuildTimeBudget() << " s to build at " << reducedFrom
                                  << " scalar steps; cut to the " << size[0]
                                  << " that fit the budget, it would be coarser than the "
                                     "transfer function needs (a feature narrower than a table "
                                     "step is what makes a build slow): the volume is drawn "
                                     "with partial pre-integration (exact) instead.");
}

//------------------------------------------------------------------------------
vtkTiledRayCastAutomaticIntegration::Settings vtkTiledRayCastIntegration::TableSettings(
  const Frame& frame, bool quantized)
{
  vtkTiledRayCastVolumeMapper* self = frame.Mapper;
  vtkTiledRayCastAutomaticIntegration::Settings settings;
  std::copy(frame.ScalarRange, frame.ScalarRange + 2, settings.ScalarRange);
  settings.MaximumError = self->GetMaximumError();
  settings.RequestedScalarSize = self->GetPreIntegrationTableScalarSize();
  settings.RequestedLengthSize = self->GetPreIntegrationTableLengthSize();
  settings.MaxTextureSize = frame.MaxTextureSize;
  settings.Max3DTextureSize = frame.Max3DTextureSize;
  // Lengths are in world units: the volume's matrix stretches them by at most its norm.
  const double longest = frame.LongestEdge * frame.ObjectToWorldNorm;
  const double reference = 0.5 * frame.TypicalEdge * frame.ObjectToWorldNorm / std::sqrt(3.0);
  // The automatic mode's lengths in steps of 2^(1/8): a mesh whose points move (a deforming mesh,
  // every frame) keeps its choice and table while its edges stay within a step; the table then
  // covers lengths up to the step above the longest edge.
  settings.MaximumLength = quantized ? Quantized(longest, std::ceil) : longest;
  settings.ReferenceLength = quantized ? Quantized(reference, std::round) : reference;
  return settings;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastIntegration::ChooseIntegration(const Frame& frame, vtkVolumeProperty* property)
{
  vtkTetMesh* mesh = frame.Mesh;
  vtkTiledRayCastVolumeMapper* self = frame.Mapper;
  const vtkTiledRayCastAutomaticIntegration::Settings settings = this->TableSettings(frame, true);
  // The transfer function by its nodes, not its time: reading a property's functions (as the
  // copy for the worker does) may create its default ones and touch its time.
  const std::vector<float>& nodes = this->TransferFunction->GetNodeTexels();
  std::vector<double> key(nodes.begin(), nodes.end());
  key.insert(key.end(),
    { static_cast<double>(mesh->GetTopologyTime()), static_cast<double>(mesh->GetScalarsTime()),
      settings.MaximumLength, settings.ReferenceLength, self->GetMaximumError(),
      static_cast<double>(self->GetPreIntegrationTableScalarSize()),
      static_cast<double>(self->GetPreIntegrationTableLengthSize()) });
  if (key != this->ChoiceKey)
  {
    // A key that changes frame after frame (every point moving and the lengths with them, a
    // transfer function being dragged) gets no choice until a frame keeps it: each choice would
    // be abandoned by the next frame's, and their tables' builds, which take every core, would
    // take them from the frames (on the H100, torus_1m's invert motion: 6.3 ms a frame back to
    // back against its wave's 2.1).
    const bool moving = this->ChoiceKeyJustChanged && this->ChoiceMade;
    this->ChoiceKey = key;
    this->ChoiceKeyJustChanged = true;
    this->ChoiceDeferred = moving;
    if (moving)
    {
      this->Automatic.Abandon();
    }
    else
    {
      // The choice samples segments of the mesh at its current points, not those of its last
      // build on the CPU.
      this->Automatic.Start(mesh, frame.MovedPoints, frame.ObjectToWorldNorm, property, settings);
    }
    // Exact until the choice is made: never a table that was not checked against the budget.
    this->AutomaticMode = vtkTiledRayCastVolumeMapper::PARTIAL_PRE_INTEGRATION;
    this->PredictedError = 0.0;
  }
  else
  {
    this->ChoiceKeyJustChanged = false;
    if (this->ChoiceDeferred)
    {
      this->ChoiceDeferred = false;
      this->Automatic.Start(mesh, frame.MovedPoints, frame.ObjectToWorldNorm, property, settings);
    }
  }
  vtkTiledRayCastAutomaticIntegration::Choice choice;
  if (!this->Automatic.Take(choice, frame.WaitForChoice || !this->ChoiceMade))
  {
    return;
  }
  this->ChoiceMade = true;
  this->AutomaticMode = choice.Mode;
  this->PredictedError = choice.PredictedError;
  if (choice.Table)
  {
    this->Table = choice.Table;
  }
  for (const vtkTiledRayCastAutomaticIntegration::Tried& tried : choice.TablesTried)
  {
    vtkDebugWithObjectMacro(
      self, << "Automatic integration: "
            << vtkTiledRayCastVolumeMapper::GetIntegrationModeAsString(tried.Mode) << " predicted "
            << tried.PredictedError << "/255 (worst segment " << tried.WorstSegmentError << ")");
  }
}
