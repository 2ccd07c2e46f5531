/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastShaderComposition.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastShaderComposition.h"

#include "vtkShaderProgram.h"
#include "vtkTiledRayCastVolumeMapper.h"
#include "vtkVolumeMapper.h"

#include "vtkTiledRayCastBlendModes.h"
#include "vtkTiledRayCastCommonFS.h"
#include "vtkTiledRayCastCompactLayout.h"
#include "vtkTiledRayCastGradientOpacity.h"
#include "vtkTiledRayCastPaperLayout.h"
#include "vtkTiledRayCastPartialPreIntegration.h"
#include "vtkTiledRayCastPreIntegration2D.h"
#include "vtkTiledRayCastPreIntegration3D.h"
#include "vtkTiledRayCastShading.h"

//------------------------------------------------------------------------------
bool vtkTiledRayCastShaderComposition::Inputs::operator==(const Inputs& other) const
{
  return this->Window == other.Window && this->Compute == other.Compute &&
    this->PaperLayout == other.PaperLayout && this->CellScalars == other.CellScalars &&
    this->TextureBufferShift == other.TextureBufferShift &&
    this->TetTextureBuffers == other.TetTextureBuffers &&
    this->PointTextureBuffers == other.PointTextureBuffers &&
    this->IntegrationMode == other.IntegrationMode && this->BlendMode == other.BlendMode &&
    this->Shading == other.Shading && this->GradientOpacity == other.GradientOpacity &&
    this->SkipEmptySpace == other.SkipEmptySpace;
}

//------------------------------------------------------------------------------
std::string vtkTiledRayCastShaderComposition::TextureBufferFetch(
  const char* name, const char* sampler, const char* texel, int buffers, int shift)
{
  // One buffer: a plain texelFetch (what the compiler inlines is the code before the split).
  // Several: texel i in buffer i >> shift at i & mask, chosen by a branch per buffer (an array of
  // samplers may only be indexed by a dynamically uniform index, and rays of one warp read
  // different buffers).
  std::string code;
  for (int k = 0; k < buffers; ++k)
  {
    code += std::string("uniform ") + sampler + " in_" + name +
      (k > 0 ? "_" + std::to_string(k) : std::string()) + ";\n";
  }
  code += std::string(texel) + " trcFetch" + name + "(uint i)\n{\n";
  if (buffers == 1)
  {
    return code + "  return texelFetch(in_" + name + ", int(i));\n}\n";
  }
  code += "  int texel = int(i & " + std::to_string((1u << shift) - 1u) + "u);\n";
  code += "  uint part = i >> " + std::to_string(shift) + "u;\n";
  for (int k = buffers - 1; k > 0; --k)
  {
    code += "  if (part == " + std::to_string(k) + "u)\n  {\n    return texelFetch(in_" + name +
      "_" + std::to_string(k) + ", texel);\n  }\n";
  }
  return code + "  return texelFetch(in_" + name + ", texel);\n}\n";
}

//------------------------------------------------------------------------------
vtkTiledRayCastShaderComposition::Replacements vtkTiledRayCastShaderComposition::Compose(
  const Inputs& inputs, const std::string& meshDefinitions)
{
  const bool paper = inputs.PaperLayout;
  const int mode = inputs.IntegrationMode;

  std::string layoutCode = paper ? vtkTiledRayCastPaperLayout : vtkTiledRayCastCompactLayout;
  if (!paper)
  {
    const int shift = inputs.TextureBufferShift;
    const int tets = inputs.TetTextureBuffers;
    std::string fetch = TextureBufferFetch("TetPoints", "usamplerBuffer", "uvec4", tets, shift) +
      TextureBufferFetch("TetNeighbors", "usamplerBuffer", "uvec4", tets, shift) +
      TextureBufferFetch("Points", "samplerBuffer", "vec4", inputs.PointTextureBuffers, shift);
    if (inputs.CellScalars)
    {
      // Cell scalars: constant per tet, the field has no gradient.
      fetch += TextureBufferFetch("TetScalars", "samplerBuffer", "vec4", tets, shift);
      vtkShaderProgram::Substitute(layoutCode, "//TRC::CellScalars::Impl",
        "float cellScalar = trcFetchTetScalars(tet).r;\n"
        "  q0.w = cellScalar;\n  q1.w = cellScalar;\n  q2.w = cellScalar;\n  q3.w = cellScalar;");
    }
    vtkShaderProgram::Substitute(layoutCode, "//TRC::MeshFetch::Dec", fetch);
  }
  const char* integration = mode == vtkTiledRayCastVolumeMapper::PRE_INTEGRATION_3D
    ? vtkTiledRayCastPreIntegration3D
    : (mode == vtkTiledRayCastVolumeMapper::PRE_INTEGRATION_2D
          ? vtkTiledRayCastPreIntegration2D
          : vtkTiledRayCastPartialPreIntegration);
  std::string integrationCode = integration;
  if (inputs.BlendMode != vtkVolumeMapper::COMPOSITE_BLEND)
  {
    // The blend modes evaluate the partial pre-integration's node list and bring their own
    // trcIntegrate.
    vtkShaderProgram::Substitute(
      integrationCode, "void trcIntegrate(", "void trcIntegrateComposite(", false);
    integrationCode = "#define TRC_BLEND_MODE\n" + integrationCode + vtkTiledRayCastBlendModes;
  }
  else
  {
    // Shaded walks, or walks with gradient opacity, only where the property asks: the walk
    // without them stays as it is.
    if (inputs.Shading)
    {
      integrationCode = "#define TRC_SHADING\n" + integrationCode + vtkTiledRayCastShading;
    }
    if (inputs.GradientOpacity)
    {
      integrationCode =
        "#define TRC_GRADIENT_OPACITY\n" + integrationCode + vtkTiledRayCastGradientOpacity;
    }
  }
  return {
    { "//TRC::Common::Dec", meshDefinitions + vtkTiledRayCastCommonFS },
    { "//TRC::Layout::Dec", layoutCode },
    { "//TRC::Integration::Dec", integrationCode },
  };
}
