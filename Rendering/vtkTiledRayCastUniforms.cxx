/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastUniforms.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastUniforms.h"

#include "vtkShaderProgram.h"
#include "vtkTetMesh.h"
#include "vtkTetMeshPaperLayout.h"
#include "vtkTextureObject.h"
#include "vtkTiledRayCastFrameGeometry.h"
#include "vtkTiledRayCastGradientOpacityNodes.h"
#include "vtkTiledRayCastIntegration.h"
#include "vtkTiledRayCastLighting.h"
#include "vtkTiledRayCastMeshBuild.h"
#include "vtkTiledRayCastMeshTextures.h"
#include "vtkTiledRayCastOpaqueDepth.h"
#include "vtkTiledRayCastTransferFunction.h"
#include "vtkTiledRayCastVisibleMesh.h"
#include "vtkTiledRayCastVolumeMapper.h"
#include "vtkVolumeMapper.h"

#include <algorithm>
#include <limits>

//------------------------------------------------------------------------------
void vtkTiledRayCastUniforms::SetFrameUniforms(vtkShaderProgram* p)
{
  const vtkTiledRayCastFrameGeometry& g = *this->Part.Geometry;
  const float viewport[2] = { static_cast<float>(this->Part.ImageSize[0]),
    static_cast<float>(this->Part.ImageSize[1]) };
  p->SetUniform2f("in_viewportSize", viewport);
  p->SetUniform3f("in_rayOrigin0", g.RayOrigin[0]);
  p->SetUniform3f("in_rayOriginX", g.RayOrigin[1]);
  p->SetUniform3f("in_rayOriginY", g.RayOrigin[2]);
  p->SetUniform3f("in_rayDir0", g.RayDir[0]);
  p->SetUniform3f("in_rayDirX", g.RayDir[1]);
  p->SetUniform3f("in_rayDirY", g.RayDir[2]);
  p->SetUniform3f("in_wNear", g.WNear);
  p->SetUniform3f("in_wFar", g.WFar);
  p->SetUniformf("in_lambdaNear", g.LambdaNear);
  p->SetUniformMatrix3x3("in_objectToWorld", const_cast<float*>(g.ObjectToWorld));
  p->SetUniformMatrix4x4("in_objectToClip", const_cast<float*>(g.ObjectToClip));
  p->SetUniform4f("in_nearPlane", g.NearPlane);
  p->SetUniformi("in_numberOfClippingPlanes", g.NumberOfClippingPlanes);
  if (g.NumberOfClippingPlanes > 0)
  {
    p->SetUniform4fv("in_clippingPlanes", g.NumberOfClippingPlanes, g.ClippingPlanes);
  }
  // In a group's frame only the first volume's scene depth is active: the group sets that one.
  const int opaqueDepthUnit = this->Part.OpaqueDepth->GetTexture()->GetTextureUnit();
  if (opaqueDepthUnit >= 0)
  {
    p->SetUniformi("in_opaqueDepth", opaqueDepthUnit);
  }
  p->SetUniformf("in_earlyTerminationOpacity",
    static_cast<float>(this->Part.Mapper->GetEarlyRayTerminationOpacity()));
}

//------------------------------------------------------------------------------
void vtkTiledRayCastUniforms::SetCoverageUniforms(vtkShaderProgram* p)
{
  // Pixel centres are tested against the faces' corners in float pixel coordinates, whose
  // rounding grows with the viewport: the tolerance covers it (a few units in the last place).
  // The dilation covers the rasteriser's snapping of corners (1/256 px on current GPUs and on
  // llvmpipe) and the tolerance, with a margin.
  const float extent =
    static_cast<float>(std::max(this->Part.ImageSize[0], this->Part.ImageSize[1]));
  const float tolerance = 8.0f * extent * std::numeric_limits<float>::epsilon();
  p->SetUniformf("in_coverageTolerance", tolerance);
  p->SetUniformf("in_coverageDilation", 1.0f / 64.0f + tolerance);
}

//------------------------------------------------------------------------------
void vtkTiledRayCastUniforms::SetMeshUniforms(vtkShaderProgram* p)
{
  this->Part.MeshTextures->SetUniforms(p);
  this->Part.VisibleMesh->SetUniforms(p);
  if (auto* paper = vtkTetMeshPaperLayout::SafeDownCast(this->Part.Mesh->GetLayout()))
  {
    p->SetUniformi("in_paperWidth", paper->GetTextureWidth());
  }
}

//------------------------------------------------------------------------------
void vtkTiledRayCastUniforms::SetBlendUniforms(vtkShaderProgram* p)
{
  // Scalars and transfer-function nodes are shifted and scaled on the GPU
  // (vtkTetMesh::GetScalarShift, GetScalarScale).
  const double* meshRange = this->Part.Mesh->ScalarRange;
  const double shift = vtkTetMesh::ComputeScalarShift(meshRange);
  const double scale = vtkTetMesh::ComputeScalarScale(meshRange);
  const float range[2] = { static_cast<float>((meshRange[0] - shift) * scale),
    static_cast<float>((meshRange[1] - shift) * scale) };
  const double* average = this->Part.Mapper->GetAverageIPScalarRange();
  const float averageRange[2] = { static_cast<float>(
                                    std::max((average[0] - shift) * scale, -3.0e38)),
    static_cast<float>(std::min((average[1] - shift) * scale, 3.0e38)) };
  p->SetUniformi("in_blendMode", this->Part.Mapper->GetBlendMode());
  p->SetUniform2f("in_blendScalarRange", range);
  p->SetUniform2f("in_averageRange", averageRange);
  // The unit distance the node list's attenuations were divided by: opacity = tau * distance.
  p->SetUniformf("in_opacityUnitDistance",
    static_cast<float>(this->Part.Integration->GetTransferFunction()->GetUnitDistance()));
}

//------------------------------------------------------------------------------
void vtkTiledRayCastUniforms::SetShadingUniforms(vtkShaderProgram* p)
{
  const vtkTiledRayCastLighting& lighting = *this->Part.Lighting;
  const vtkTiledRayCastGradientOpacityNodes& gradientOpacity = *this->Part.GradientOpacity;
  if (lighting.Enabled || gradientOpacity.Enabled)
  {
    p->SetUniformMatrix3x3("in_gradientToWorld", const_cast<float*>(lighting.GradientToWorld));
  }
  if (gradientOpacity.Enabled)
  {
    p->SetUniformi("in_gradientOpacityNodes", gradientOpacity.NumberOfNodes);
    // The gradients the shaders compute are in the GPU's scaled scalar units
    // (vtkTetMesh::GetScalarScale): so are the nodes' magnitudes, scaled in double.
    const double scale = vtkTetMesh::ComputeScalarScale(this->Part.Mesh->ScalarRange);
    float nodes[vtkTiledRayCastGradientOpacityNodes::MaximumNodes][2];
    for (int i = 0; i < gradientOpacity.NumberOfNodes; ++i)
    {
      nodes[i][0] = static_cast<float>(gradientOpacity.Nodes[i][0] * scale);
      nodes[i][1] = gradientOpacity.Nodes[i][1];
    }
    p->SetUniform2fv("in_gradientOpacity", gradientOpacity.NumberOfNodes, nodes[0]);
    p->SetUniformi("in_gradientOpacityClamping", gradientOpacity.Clamping);
  }
  if (!lighting.Enabled)
  {
    return;
  }
  p->SetUniform4f("in_material", lighting.Material);
  p->SetUniformi("in_twoSidedLighting", lighting.TwoSided);
  p->SetUniformi("in_numberOfLights", lighting.NumberOfLights);
  if (lighting.NumberOfLights > 0)
  {
    p->SetUniform3fv("in_lightToLight", lighting.NumberOfLights, lighting.ToLight);
    p->SetUniform3fv("in_lightDiffuse", lighting.NumberOfLights, lighting.Diffuse);
    p->SetUniform3fv("in_lightSpecular", lighting.NumberOfLights, lighting.Specular);
  }
}

//------------------------------------------------------------------------------
void vtkTiledRayCastUniforms::SetIntegrationUniforms(vtkShaderProgram* p)
{
  const int mode = this->Part.Integration->GetMode(this->Part.Mapper);
  this->Part.Integration->SetUniforms(p, mode,
    vtkTetMesh::ComputeScalarShift(this->Part.Mesh->ScalarRange),
    vtkTetMesh::ComputeScalarScale(this->Part.Mesh->ScalarRange));
  if (mode == vtkTiledRayCastVolumeMapper::PARTIAL_PRE_INTEGRATION &&
    this->Part.Mapper->GetBlendMode() != vtkVolumeMapper::COMPOSITE_BLEND)
  {
    this->SetBlendUniforms(p);
  }
  this->SetShadingUniforms(p);
}

//------------------------------------------------------------------------------
void vtkTiledRayCastUniforms::SetSampleScaleUniforms(vtkShaderProgram* p)
{
  const float scale[2] = { static_cast<float>(this->Part.ImageSize[0]) / this->Part.Viewport[2],
    static_cast<float>(this->Part.ImageSize[1]) / this->Part.Viewport[3] };
  p->SetUniform2f("in_sampleScale", scale);
  p->SetUniform2i("in_imageSize", this->Part.ImageSize);
}
