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
    this->IntegrationMode == other.IntegrationMode && this->BlendMode == other.BlendMode &&
    this->Shading == other.Shading && this->GradientOpacity == other.GradientOpacity &&
    this->SkipEmptySpace == other.SkipEmptySpace;
}

//------------------------------------------------------------------------------
vtkTiledRayCastShaderComposition::Replacements vtkTiledRayCastShaderComposition::Compose(
  const Inputs& inputs, const std::string& meshDefinitions)
{
  const bool paper = inputs.PaperLayout;
  const int mode = inputs.IntegrationMode;

  std::string layoutCode = paper ? vtkTiledRayCastPaperLayout : vtkTiledRayCastCompactLayout;
  if (!paper && inputs.CellScalars)
  {
    // Cell scalars: constant per tet, the field has no gradient.
    vtkShaderProgram::Substitute(
      layoutCode, "//TRC::CellScalars::Dec", "uniform samplerBuffer in_TetScalars;");
    vtkShaderProgram::Substitute(layoutCode, "//TRC::CellScalars::Impl",
      "float cellScalar = texelFetch(in_TetScalars, int(tet)).r;\n"
      "  q0.w = cellScalar;\n  q1.w = cellScalar;\n  q2.w = cellScalar;\n  q3.w = cellScalar;");
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
