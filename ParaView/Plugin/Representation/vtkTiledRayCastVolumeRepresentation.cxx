/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastVolumeRepresentation.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastVolumeRepresentation.h"

#include "vtkCellArray.h"
#include "vtkColorTransferFunction.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPVLODVolume.h"
#include "vtkPVRenderView.h"
#include "vtkScalarsToColors.h"
#include "vtkTiledRayCastStatistics.h"
#include "vtkTiledRayCastVolumeSubProxyOverride.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"
#include "vtkVolumeRepresentationPreprocessor.h"

namespace
{
// Whether this process is one rank of several (ParaView's server or pvbatch under MPI).
bool IsParallel()
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  return controller && controller->GetNumberOfProcesses() > 1;
}
}

vtkStandardNewMacro(vtkTiledRayCastVolumeRepresentation);

//------------------------------------------------------------------------------
vtkTiledRayCastVolumeRepresentation::vtkTiledRayCastVolumeRepresentation()
{
  // The mapper is the representation's own rather than a mapper subproxy: the server-side
  // proxy class of ParaView 5.11 registers its four mappers by name and knows of no fifth.
  this->AddVolumeMapper(GetTiledRayCastMapperName(), this->TiledRayCastMapper);
}

//------------------------------------------------------------------------------
vtkTiledRayCastVolumeRepresentation::~vtkTiledRayCastVolumeRepresentation() = default;

//------------------------------------------------------------------------------
void vtkTiledRayCastVolumeRepresentation::InitializeProcess()
{
  vtkTiledRayCastVolumeSubProxyOverride::Install();
}

//------------------------------------------------------------------------------
void vtkTiledRayCastVolumeRepresentation::SetTiledRayCastIntegrationMode(int mode)
{
  this->TiledRayCastMapper->SetIntegrationMode(mode);
}

//------------------------------------------------------------------------------
int vtkTiledRayCastVolumeRepresentation::GetTiledRayCastIntegrationMode()
{
  return this->TiledRayCastMapper->GetIntegrationMode();
}

//------------------------------------------------------------------------------
void vtkTiledRayCastVolumeRepresentation::SetTiledRayCastPipeline(int pipeline)
{
  this->TiledRayCastMapper->SetPipeline(pipeline);
}

//------------------------------------------------------------------------------
int vtkTiledRayCastVolumeRepresentation::GetTiledRayCastPipeline()
{
  return this->TiledRayCastMapper->GetPipeline();
}

//------------------------------------------------------------------------------
void vtkTiledRayCastVolumeRepresentation::SetTiledRayCastTileSize(int size)
{
  this->TiledRayCastMapper->SetTileSize(size);
}

//------------------------------------------------------------------------------
int vtkTiledRayCastVolumeRepresentation::GetTiledRayCastTileSize()
{
  return this->TiledRayCastMapper->GetTileSize();
}

//------------------------------------------------------------------------------
void vtkTiledRayCastVolumeRepresentation::SetTiledRayCastEarlyTerminationOpacity(double opacity)
{
  this->TiledRayCastMapper->SetEarlyRayTerminationOpacity(opacity);
}

//------------------------------------------------------------------------------
double vtkTiledRayCastVolumeRepresentation::GetTiledRayCastEarlyTerminationOpacity()
{
  return this->TiledRayCastMapper->GetEarlyRayTerminationOpacity();
}

//------------------------------------------------------------------------------
void vtkTiledRayCastVolumeRepresentation::SetTiledRayCastEmptySpaceSkipping(int skipping)
{
  this->TiledRayCastMapper->SetEmptySpaceSkipping(skipping != 0);
}

//------------------------------------------------------------------------------
int vtkTiledRayCastVolumeRepresentation::GetTiledRayCastEmptySpaceSkipping()
{
  return this->TiledRayCastMapper->GetEmptySpaceSkipping() ? 1 : 0;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastVolumeRepresentation::SetTiledRayCastMaximumError(double error)
{
  this->TiledRayCastMapper->SetMaximumError(error);
}

//------------------------------------------------------------------------------
double vtkTiledRayCastVolumeRepresentation::GetTiledRayCastMaximumError()
{
  return this->TiledRayCastMapper->GetMaximumError();
}

//------------------------------------------------------------------------------
void vtkTiledRayCastVolumeRepresentation::SetTiledRayCastSplitBoundaryCells(int split)
{
  if (this->TiledRayCastSplitBoundaryCells != split)
  {
    this->TiledRayCastSplitBoundaryCells = split;
    // The redistribution is part of the data update.
    this->MarkModified();
  }
}

//------------------------------------------------------------------------------
const char* vtkTiledRayCastVolumeRepresentation::GetTiledRayCastStatistics()
{
  vtkTiledRayCastStatistics* statistics = this->TiledRayCastMapper->GetStatistics();
  this->StatisticsSummary = statistics->GetRendered()
    ? statistics->GetSummary() + "; integration: " +
      vtkTiledRayCastVolumeMapper::GetIntegrationModeAsString(statistics->GetIntegrationMode())
    : std::string();
  return this->StatisticsSummary.c_str();
}

//------------------------------------------------------------------------------
void vtkTiledRayCastVolumeRepresentation::SetTiledRayCastSynchronousStatistics(int synchronous)
{
  this->TiledRayCastMapper->SetSynchronousStatistics(synchronous != 0);
}

//------------------------------------------------------------------------------
int vtkTiledRayCastVolumeRepresentation::GetTiledRayCastSynchronousStatistics()
{
  return this->TiledRayCastMapper->GetSynchronousStatistics() ? 1 : 0;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastVolumeRepresentation::UpdateMapperParameters()
{
  this->Superclass::UpdateMapperParameters();
  if (this->GetActiveVolumeMapper() != this->TiledRayCastMapper)
  {
    return;
  }
  // As ParaView does for its smart mappers (vtkUnstructuredGridVolumeRepresentation): the
  // colour map's vector mode with independent components, else the first component.
  vtkColorTransferFunction* color = this->Property->GetRGBTransferFunction(0);
  const bool independent = this->Property->GetIndependentComponents() != 0;
  this->TiledRayCastMapper->SetVectorMode(
    independent && color ? color->GetVectorMode() : vtkScalarsToColors::COMPONENT);
  this->TiledRayCastMapper->SetVectorComponent(
    independent && color ? color->GetVectorComponent() : 0);
}

//------------------------------------------------------------------------------
int vtkTiledRayCastVolumeRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (!this->Superclass::RequestData(request, inputVector, outputVector))
  {
    return 0;
  }
  auto* piece = vtkUnstructuredGrid::SafeDownCast(this->Preprocessor->GetOutputDataObject(0));
  if (IsParallel() && piece && piece->GetNumberOfCells() > 0)
  {
    vtkNew<vtkCellArray> cells;
    cells->DeepCopy(piece->GetCells());
    piece->SetCells(piece->GetCellTypesArray(), cells);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkTiledRayCastVolumeRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* requestType, vtkInformation* inInfo, vtkInformation* outInfo)
{
  if (!this->Superclass::ProcessViewRequest(requestType, inInfo, outInfo))
  {
    return 0;
  }
  if (requestType == vtkPVView::REQUEST_UPDATE())
  {
    if (this->GetActiveVolumeMapper() == this->TiledRayCastMapper &&
      this->TiledRayCastSplitBoundaryCells)
    {
      vtkPVRenderView::SetRedistributionModeToSplitBoundaryCells(inInfo, this);
    }
    // The cut at the partition planes leaves degenerate cells and duplicate points wherever a
    // plane passes through or next to a point: ours, not the user's, and not worth a warning from
    // every rank (the validation report still counts them).
    this->TiledRayCastMapper->SetWarnAboutDegenerateCells(
      !(this->TiledRayCastSplitBoundaryCells && IsParallel()));
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastVolumeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TiledRayCastMapper: " << this->TiledRayCastMapper.GetPointer() << "\n";
  os << indent << "TiledRayCastSplitBoundaryCells: " << this->TiledRayCastSplitBoundaryCells
     << "\n";
}
