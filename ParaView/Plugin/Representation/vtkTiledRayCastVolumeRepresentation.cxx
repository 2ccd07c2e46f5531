/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastVolumeRepresentation.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastVolumeRepresentation.h"

#include "vtkColorTransferFunction.h"
#include "vtkObjectFactory.h"
#include "vtkPVLODVolume.h"
#include "vtkScalarsToColors.h"
#include "vtkTiledRayCastStatistics.h"
#include "vtkVolumeProperty.h"

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
const char* vtkTiledRayCastVolumeRepresentation::GetTiledRayCastStatistics()
{
  vtkTiledRayCastStatistics* statistics = this->TiledRayCastMapper->GetStatistics();
  this->StatisticsSummary = statistics->GetRendered() ? statistics->GetSummary() : std::string();
  return this->StatisticsSummary.c_str();
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
void vtkTiledRayCastVolumeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TiledRayCastMapper: " << this->TiledRayCastMapper.GetPointer() << "\n";
}
