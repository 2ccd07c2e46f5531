/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastStatistics.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastStatistics.h"

#include "vtkObjectFactory.h"

#include <algorithm>
#include <sstream>
#include <string>

vtkStandardNewMacro(vtkTiledRayCastStatistics);

//------------------------------------------------------------------------------
vtkTiledRayCastStatistics::vtkTiledRayCastStatistics() = default;

//------------------------------------------------------------------------------
vtkTiledRayCastStatistics::~vtkTiledRayCastStatistics()
{
  this->SetPipeline(nullptr);
}

//------------------------------------------------------------------------------
void vtkTiledRayCastStatistics::ResetFrameCounts()
{
  this->Rendered = false;
  this->SceneDepthCopied = false;
  this->DepthPeelingStage = 0;
  this->DepthPeelingEntriesReused = false;
  this->ImageSize[0] = this->ImageSize[1] = 0;
  this->NumberOfRays = 0;
  this->NumberOfLayers = 0;
  this->NumberOfPeelPasses = 0;
  this->NumberOfNearPlaneRays = 0;
  this->NumberOfTiles = 0;
  this->NumberOfTilesSkipped = 0;
  this->NumberOfRayCastPasses = 0;
  this->MinimumPassesPerTile = 0;
  this->MedianPassesPerTile = 0;
  this->MaximumPassesPerTile = 0;
  this->NumberOfZUpdatePasses = 0;
  this->NumberOfOcclusionQueries = 0;
  this->NumberOfRaysTerminatedEarly = 0;
  this->NumberOfEntries = 0;
  this->NumberOfIncompleteRays = 0;
  this->NumberOfGroupedVolumes = 0;
  this->NumberOfMixedRays = 0;
  this->GroupCodeShared = false;
  this->NumberOfVolumeSetsInDepthOrder = 0;
  this->NumberOfShaderCompositions = 0;
  this->NumberOfSteps = 0;
  this->MaximumStepsPerRay = 0;
  this->MeshBuildTime = 0;
  this->MeshRebuild = 0;
  this->TransferFunctionBuildTime = 0;
  this->RenderTime = 0;
  this->UploadedBytes = 0;
  this->MeshUploadTime = 0;
  this->PassesPerTile.clear();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkTiledRayCastStatistics::FinishTilePasses()
{
  std::vector<int>& passes = this->PassesPerTile;
  if (passes.empty())
  {
    this->MinimumPassesPerTile = this->MaximumPassesPerTile = 0;
    this->MedianPassesPerTile = 0;
    return;
  }
  std::vector<int> sorted(passes);
  std::sort(sorted.begin(), sorted.end());
  const size_t n = sorted.size();
  this->MinimumPassesPerTile = sorted.front();
  this->MaximumPassesPerTile = sorted.back();
  this->MedianPassesPerTile =
    n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + static_cast<double>(sorted[n / 2]));
  this->Modified();
}

//------------------------------------------------------------------------------
std::string vtkTiledRayCastStatistics::GetSummary() const
{
  std::ostringstream text;
  if (!this->Rendered)
  {
    text << "nothing rendered";
    return text.str();
  }
  // Each pipeline's own counts: entries and tets per ray (compute), peels and passes per tile
  // (fragment).
  const bool compute = this->Pipeline && std::string(this->Pipeline) == "Compute";
  text << (this->Pipeline ? this->Pipeline : "?") << " pipeline, " << this->ImageSize[0] << "x"
       << this->ImageSize[1] << " px";
  if (this->ImageSampleDistance != 1.0)
  {
    text << " (image sample distance " << this->ImageSampleDistance << ")";
  }
  text << ", " << this->NumberOfRays << " rays";
  if (compute)
  {
    text << " (" << this->GetMeanStepsPerRay() << " tets per ray, max " << this->MaximumStepsPerRay
         << "), " << this->NumberOfEntries << " entries";
    if (this->NumberOfIncompleteRays > 0)
    {
      text << " (" << this->NumberOfIncompleteRays << " rays incomplete)";
    }
    if (this->NumberOfGroupedVolumes > 1)
    {
      text << ", " << this->NumberOfGroupedVolumes << " overlapping volumes in one traversal ("
           << this->NumberOfMixedRays << " rays through their mixture"
           << (this->GroupCodeShared ? "; one copy of their code)" : ")");
    }
    text << ", " << this->NumberOfLayers << " layers, " << this->NumberOfTiles << " tiles ("
         << this->NumberOfTilesSkipped << " empty)";
  }
  else
  {
    text << ", " << this->NumberOfLayers << " layers (" << this->NumberOfPeelPasses
         << " peel passes), " << this->NumberOfTiles << " tiles (" << this->NumberOfTilesSkipped
         << " skipped), " << this->NumberOfRayCastPasses << " ray-casting passes (per tile min "
         << this->MinimumPassesPerTile << ", median " << this->MedianPassesPerTile << ", max "
         << this->MaximumPassesPerTile << ")";
  }
  text << ", " << this->NumberOfRaysTerminatedEarly << " rays terminated early, "
       << (this->SceneDepthCopied ? "scene depth copied, " : "no scene depth, ");
  if (this->DepthPeelingStage > 0)
  {
    text << "depth peeling stage " << this->DepthPeelingStage << " (draw "
         << this->NumberOfDepthPeelingDraws << " of the frame"
         << (this->DepthPeelingEntriesReused ? ", the first draw's entries" : "") << "), ";
  }
  text << this->NumberOfVisibleTetrahedra << " tets visible, " << this->NumberOfEntryFaces
       << " entry faces; GPU ms: " << (compute ? "entry pass " : "first hit ")
       << this->FirstHitTime;
  if (!compute)
  {
    text << ", peeling " << this->PeelingTime;
  }
  text << ", ray casting " << this->RayCastingTime << ", compositing " << this->CompositingTime
       << ", total " << this->TotalGPUTime << "; GPU memory " << this->GetTotalGPUBytes()
       << " B (mesh " << this->MeshBytes << " B, " << this->MeshBytesPerTetrahedron << " B/tet"
       << (this->NumberOfMeshTextures > 4
              ? ", in " + std::to_string(this->NumberOfMeshTextures) + " textures"
              : std::string())
       << ")";
  return text.str();
}

//------------------------------------------------------------------------------
void vtkTiledRayCastStatistics::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Rendered: " << this->Rendered << "\n";
  os << indent << "SceneDepthCopied: " << this->SceneDepthCopied << "\n";
  os << indent << "DepthPeelingStage: " << this->DepthPeelingStage << "\n";
  os << indent << "NumberOfDepthPeelingDraws: " << this->NumberOfDepthPeelingDraws << "\n";
  os << indent << "DepthPeelingEntriesReused: " << this->DepthPeelingEntriesReused << "\n";
  os << indent << "ImageSize: " << this->ImageSize[0] << " " << this->ImageSize[1] << "\n";
  os << indent << "ImageSampleDistance: " << this->ImageSampleDistance << "\n";
  os << indent << "NumberOfRays: " << this->NumberOfRays << "\n";
  os << indent << "NumberOfLayers: " << this->NumberOfLayers << "\n";
  os << indent << "NumberOfPeelPasses: " << this->NumberOfPeelPasses << "\n";
  os << indent << "NumberOfNearPlaneRays: " << this->NumberOfNearPlaneRays << "\n";
  os << indent << "NumberOfTiles: " << this->NumberOfTiles << "\n";
  os << indent << "NumberOfTilesSkipped: " << this->NumberOfTilesSkipped << "\n";
  os << indent << "NumberOfRayCastPasses: " << this->NumberOfRayCastPasses << "\n";
  os << indent << "MinimumPassesPerTile: " << this->MinimumPassesPerTile << "\n";
  os << indent << "MedianPassesPerTile: " << this->MedianPassesPerTile << "\n";
  os << indent << "MaximumPassesPerTile: " << this->MaximumPassesPerTile << "\n";
  os << indent << "NumberOfZUpdatePasses: " << this->NumberOfZUpdatePasses << "\n";
  os << indent << "NumberOfOcclusionQueries: " << this->NumberOfOcclusionQueries << "\n";
  os << indent << "NumberOfRaysTerminatedEarly: " << this->NumberOfRaysTerminatedEarly << "\n";
  os << indent << "Pipeline: " << (this->Pipeline ? this->Pipeline : "(none)") << "\n";
  os << indent << "NumberOfEntries: " << this->NumberOfEntries << "\n";
  os << indent << "NumberOfIncompleteRays: " << this->NumberOfIncompleteRays << "\n";
  os << indent << "NumberOfGroupedVolumes: " << this->NumberOfGroupedVolumes << "\n";
  os << indent << "NumberOfMixedRays: " << this->NumberOfMixedRays << "\n";
  os << indent << "GroupCodeShared: " << (this->GroupCodeShared ? "On" : "Off") << "\n";
  os << indent << "NumberOfVolumeSetsInDepthOrder: " << this->NumberOfVolumeSetsInDepthOrder
     << "\n";
  os << indent << "NumberOfShaderCompositions: " << this->NumberOfShaderCompositions << "\n";
  os << indent << "NumberOfSteps: " << this->NumberOfSteps << "\n";
  os << indent << "MaximumStepsPerRay: " << this->MaximumStepsPerRay << "\n";
  os << indent << "FirstHitTime: " << this->FirstHitTime << "\n";
  os << indent << "PeelingTime: " << this->PeelingTime << "\n";
  os << indent << "RayCastingTime: " << this->RayCastingTime << "\n";
  os << indent << "CompositingTime: " << this->CompositingTime << "\n";
  os << indent << "TotalGPUTime: " << this->TotalGPUTime << "\n";
  os << indent << "MeshBuildTime: " << this->MeshBuildTime << "\n";
  os << indent << "MeshRebuild: " << this->MeshRebuild << "\n";
  os << indent << "TransferFunctionBuildTime: " << this->TransferFunctionBuildTime << "\n";
  os << indent << "RenderTime: " << this->RenderTime << "\n";
  os << indent << "UploadedBytes: " << this->UploadedBytes << "\n";
  os << indent << "MeshUploadTime: " << this->MeshUploadTime << "\n";
  os << indent << "MeshBytes: " << this->MeshBytes << "\n";
  os << indent << "MeshBytesPerTetrahedron: " << this->MeshBytesPerTetrahedron << "\n";
  os << indent << "NumberOfMeshTextures: " << this->NumberOfMeshTextures << "\n";
  os << indent << "TransferFunctionBytes: " << this->TransferFunctionBytes << "\n";
  os << indent << "RenderTargetBytes: " << this->RenderTargetBytes << "\n";
  os << indent << "NumberOfTransferFunctionNodes: " << this->NumberOfTransferFunctionNodes << "\n";
  os << indent << "IntegrationMode: " << this->IntegrationMode << "\n";
  os << indent << "PredictedError: " << this->PredictedError << "\n";
  os << indent << "PreIntegrationTableSize: " << this->PreIntegrationTableSize[0] << " "
     << this->PreIntegrationTableSize[1] << " " << this->PreIntegrationTableSize[2] << "\n";
  os << indent << "NumberOfVisibleTetrahedra: " << this->NumberOfVisibleTetrahedra << "\n";
  os << indent << "NumberOfEntryFaces: " << this->NumberOfEntryFaces << "\n";
}
