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

#include <cmath>

//------------------------------------------------------------------------------
vtkTiledRayCastIntegration::vtkTiledRayCastIntegration() = default;

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
  return mode == vtkTiledRayCastVolumeMapper::AUTOMATIC_INTEGRATION ? this->AutomaticMode : mode;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastIntegration::SetUniforms(vtkShaderProgram* p, int mode, double scalarShift)
{
  this->Textures.SetUniforms(p, mode, this->TransferFunction, this->Table, scalarShift);
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

  vtkIdType uploaded = 0;
  const int mode = this->GetMode(self);
  stats->SetIntegrationMode(mode);
  stats->SetPredictedError(
    self->GetIntegrationMode() == vtkTiledRayCastVolumeMapper::AUTOMATIC_INTEGRATION
      ? this->PredictedError
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
    this->ConfigureTable(frame, mode);
    table->Update(property, this->TransferFunction, frame.ScalarRange);
    if (!this->Textures.UpdateTable(window, table, mode, self, uploaded, error))
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
void vtkTiledRayCastIntegration::ConfigureTable(const Frame& frame, int mode)
{
  vtkTiledRayCastVolumeMapper* self = frame.Mapper;
  vtkTiledRayCastPreIntegrationTable* table = this->Table;
  const bool is3D = mode == vtkTiledRayCastVolumeMapper::PRE_INTEGRATION_3D;
  table->SetDimension(is3D ? 3 : 2);
  table->SetRequestedScalarSize(self->GetPreIntegrationTableScalarSize());
  table->SetRequestedLengthSize(self->GetPreIntegrationTableLengthSize());
  table->SetMaximumSize(is3D ? frame.Max3DTextureSize : frame.MaxTextureSize);
  // Lengths are in world units: the volume's matrix stretches them by at most its norm.
  table->SetMaximumLength(frame.LongestEdge * frame.ObjectToWorldNorm);
  table->SetReferenceLength(0.5 * frame.TypicalEdge * frame.ObjectToWorldNorm / std::sqrt(3.0));
}

//------------------------------------------------------------------------------
void vtkTiledRayCastIntegration::ChooseIntegration(const Frame& frame, vtkVolumeProperty* property)
{
  vtkTetMesh* mesh = frame.Mesh;
  const double norm = frame.ObjectToWorldNorm;
  const std::vector<double> key = { static_cast<double>(this->TransferFunction->GetMTime()),
    static_cast<double>(mesh->GetMTime()), norm, frame.Mapper->GetMaximumError(),
    static_cast<double>(frame.Mapper->GetPreIntegrationTableScalarSize()),
    static_cast<double>(frame.Mapper->GetPreIntegrationTableLengthSize()) };
  if (key == this->ChoiceKey)
  {
    return;
  }
  this->ChoiceKey = key;
  // Cheapest first (measured on the H200: the 2D table, the 3D table, partial pre-integration);
  // each table is kept if its predicted error is within the budget.
  this->AutomaticMode = vtkTiledRayCastVolumeMapper::PARTIAL_PRE_INTEGRATION;
  this->PredictedError = 0.0;
  this->Choice.SampleSegments(mesh, norm);
  if (!this->Choice.SetProperty(property))
  {
    return;
  }
  for (int mode : { vtkTiledRayCastVolumeMapper::PRE_INTEGRATION_2D,
         vtkTiledRayCastVolumeMapper::PRE_INTEGRATION_3D })
  {
    this->ConfigureTable(frame, mode);
    if (!this->Table->Update(property, this->TransferFunction, frame.ScalarRange))
    {
      return;
    }
    const double error = this->Choice.PredictError(this->Table);
    vtkDebugWithObjectMacro(frame.Mapper,
      << "Automatic integration: " << vtkTiledRayCastVolumeMapper::GetIntegrationModeAsString(mode)
      << " predicted " << error << "/255 (worst segment " << this->Choice.GetWorstSegmentError()
      << ")");
    if (error <= frame.Mapper->GetMaximumError())
    {
      this->AutomaticMode = mode;
      this->PredictedError = error;
      return;
    }
  }
}
