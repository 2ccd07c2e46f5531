/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastVolumeMapper.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastVolumeMapper.h"

#include "vtkAlgorithm.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataObjectTree.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkTetMeshValidationReport.h"
#include "vtkTiledRayCastStatistics.h"

// The OpenGL implementation comes through the object factory.
vtkAbstractObjectFactoryNewMacro(vtkTiledRayCastVolumeMapper);

//------------------------------------------------------------------------------
vtkTiledRayCastVolumeMapper::vtkTiledRayCastVolumeMapper()
  : Statistics(vtkTiledRayCastStatistics::New())
  , ValidationReport(vtkTetMeshValidationReport::New())
  , ScalarSelection(vtkTetScalarSelection::New())
{
}

//------------------------------------------------------------------------------
vtkTiledRayCastVolumeMapper::~vtkTiledRayCastVolumeMapper()
{
  this->Statistics->Delete();
  this->ValidationReport->Delete();
  this->ScalarSelection->Delete();
}

//------------------------------------------------------------------------------
// VectorMode and VectorComponent live in the scalar selection; a change to either is a change to
// the mapper, as for its other settings (and only a change: ParaView sets them at every update).
void vtkTiledRayCastVolumeMapper::SetVectorMode(int mode)
{
  const vtkMTimeType before = this->ScalarSelection->GetMTime();
  this->ScalarSelection->SetVectorMode(mode);
  if (this->ScalarSelection->GetMTime() != before)
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkTiledRayCastVolumeMapper::SetVectorComponent(int component)
{
  const vtkMTimeType before = this->ScalarSelection->GetMTime();
  this->ScalarSelection->SetVectorComponent(component);
  if (this->ScalarSelection->GetMTime() != before)
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkTetScalarSelection* vtkTiledRayCastVolumeMapper::GetScalarSelection()
{
  // vtkAbstractVolumeMapper holds the array settings (its setters, and its subclasses, write
  // its members): copied in here rather than mirrored as they are set, so that they are kept
  // in one place and the object handed along is never stale. The copy changes the selection's
  // modification time, never the mapper's, which counts only what its users set: the mapper's
  // own GetMTime() leaves the selection out.
  vtkTetScalarSelection* selection = this->ScalarSelection;
  selection->SetScalarMode(this->ScalarMode);
  selection->SetArrayAccessMode(this->ArrayAccessMode);
  selection->SetArrayId(this->ArrayId);
  selection->SetArrayName(this->ArrayName);
  return selection;
}

//------------------------------------------------------------------------------
int vtkTiledRayCastVolumeMapper::FillInputPortInformation(int port, vtkInformation* info)
{
  this->Superclass::FillInputPortInformation(port, info);
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObjectTree");
  return 1;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastVolumeMapper::SetInputData(vtkDataObjectTree* input)
{
  this->SetInputDataInternal(0, input);
}

//------------------------------------------------------------------------------
double* vtkTiledRayCastVolumeMapper::GetBounds()
{
  vtkCompositeDataSet* tree = this->GetNumberOfInputConnections(0) > 0
    ? vtkCompositeDataSet::SafeDownCast(this->GetInputDataObject(0, 0))
    : nullptr;
  if (!tree)
  {
    return this->Superclass::GetBounds();
  }
  this->Update();
  tree = vtkCompositeDataSet::SafeDownCast(this->GetInputDataObject(0, 0));
  vtkMath::UninitializeBounds(this->Bounds);
  if (tree)
  {
    tree->GetBounds(this->Bounds);
  }
  return this->Bounds;
}

//------------------------------------------------------------------------------
const char* vtkTiledRayCastVolumeMapper::GetIntegrationModeAsString()
{
  return vtkTiledRayCastVolumeMapper::GetIntegrationModeAsString(this->IntegrationMode);
}

//------------------------------------------------------------------------------
const char* vtkTiledRayCastVolumeMapper::GetIntegrationModeAsString(int mode)
{
  switch (mode)
  {
    case PRE_INTEGRATION_3D:
      return "PreIntegration3D";
    case PRE_INTEGRATION_2D:
      return "PreIntegration2D";
    case AUTOMATIC_INTEGRATION:
      return "Automatic";
    default:
      return "PartialPreIntegration";
  }
}

//------------------------------------------------------------------------------
const char* vtkTiledRayCastVolumeMapper::GetMeshLayoutAsString()
{
  return this->MeshLayout == PAPER_LAYOUT ? "Paper" : "Compact";
}

//------------------------------------------------------------------------------
int vtkTiledRayCastVolumeMapper::IsRenderSupported(vtkRenderWindow*, vtkVolumeProperty*)
{
  return 0;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastVolumeMapper::Update()
{
  if (!this->GetDataObjectInput())
  {
    this->Statistics->ResetFrameCounts();
  }
  this->Superclass::Update();
}

//------------------------------------------------------------------------------
const char* vtkTiledRayCastVolumeMapper::GetPointUpdateAsString()
{
  switch (this->PointUpdate)
  {
    case CPU_POINT_UPDATE:
      return "CPU";
    case GPU_POINT_UPDATE:
      return "GPU";
    default:
      return "Automatic";
  }
}

//------------------------------------------------------------------------------
const char* vtkTiledRayCastVolumeMapper::GetPipelineAsString()
{
  switch (this->Pipeline)
  {
    case COMPUTE_PIPELINE:
      return "Compute";
    case FRAGMENT_PIPELINE:
      return "Fragment";
    default:
      return "Automatic";
  }
}

//------------------------------------------------------------------------------
void vtkTiledRayCastVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "IntegrationMode: " << this->GetIntegrationModeAsString() << "\n";
  os << indent << "MaximumError: " << this->MaximumError << "\n";
  os << indent << "MeshLayout: " << this->GetMeshLayoutAsString() << "\n";
  os << indent << "SpatialOrdering: " << (this->SpatialOrdering ? "On" : "Off") << "\n";
  os << indent << "PointUpdate: " << this->GetPointUpdateAsString() << "\n";
  os << indent << "Pipeline: " << this->GetPipelineAsString() << "\n";
  os << indent << "TetsPerPass: " << this->TetsPerPass << "\n";
  os << indent << "OcclusionQueryInterval: " << this->OcclusionQueryInterval << "\n";
  os << indent << "TileSize: " << this->TileSize << "\n";
  os << indent << "EarlyRayTerminationOpacity: " << this->EarlyRayTerminationOpacity << "\n";
  os << indent << "ImageSampleDistance: " << this->ImageSampleDistance << "\n";
  os << indent << "MinimumImageSampleDistance: " << this->MinimumImageSampleDistance << "\n";
  os << indent << "MaximumImageSampleDistance: " << this->MaximumImageSampleDistance << "\n";
  os << indent << "AutoAdjustSampleDistances: " << (this->AutoAdjustSampleDistances ? "On" : "Off")
     << "\n";
  os << indent << "EmptySpaceSkipping: " << (this->EmptySpaceSkipping ? "On" : "Off") << "\n";
  os << indent << "BlendMode: " << this->BlendMode << "\n";
  os << indent << "AverageIPScalarRange: " << this->AverageIPScalarRange[0] << " "
     << this->AverageIPScalarRange[1] << "\n";
  os << indent << "MaximumNumberOfPassesPerLayer: " << this->MaximumNumberOfPassesPerLayer << "\n";
  os << indent << "MaximumTextureBufferSize: " << this->MaximumTextureBufferSize << "\n";
  os << indent << "MaximumTextureSize: " << this->MaximumTextureSize << "\n";
  os << indent << "MaximumGPUMemory: " << this->MaximumGPUMemory << "\n";
  os << indent << "PreIntegrationTableScalarSize: " << this->PreIntegrationTableScalarSize << "\n";
  os << indent << "PreIntegrationTableLengthSize: " << this->PreIntegrationTableLengthSize << "\n";
  os << indent << "SynchronousStatistics: " << this->SynchronousStatistics << "\n";
  os << indent << "WarnAboutDegenerateCells: " << this->WarnAboutDegenerateCells << "\n";
  os << indent << "Statistics:\n";
  this->Statistics->PrintSelf(os, indent.GetNextIndent());
  os << indent << "ValidationReport:\n";
  this->ValidationReport->PrintSelf(os, indent.GetNextIndent());
  // The array settings are vtkAbstractVolumeMapper's, printed by it.
  os << indent << "VectorMode: " << this->GetVectorMode() << "\n";
  os << indent << "VectorComponent: " << this->GetVectorComponent() << "\n";
}
