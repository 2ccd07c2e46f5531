/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastGradientOpacityNodes.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastGradientOpacityNodes
 * @brief   the property's gradient opacity function as the shaders' node list
 *
 * Gradient opacity (docs/design.md, "Gradient opacity") scales each tet's attenuation by the
 * property's gradient opacity function of component 0 at the magnitude of the tet's scalar
 * gradient (scalar units per world unit), clamped to [0, 1]. The shaders
 * (vtkTiledRayCastGradientOpacity.glsl) evaluate it from these nodes, linear in between, with
 * the function's clamping outside them, the value clamped to [0, 1]: exact for a function whose
 * intervals are linear (VTK's default midpoint 0.5 and sharpness 0); an interval of another
 * midpoint or sharpness is sampled at SamplesPerCurvedInterval points, and a function of more than
 * MaximumNodes nodes in all at MaximumNodes evenly spaced points (Approximated, for the mapper's
 * warning).
 *
 * Off (Enabled false) without a function, when it is disabled, when it is 1 at every node with
 * clamping on (ParaView's default: it changes nothing), and under blend modes other than
 * composite (VTK's mappers use it there only).
 *
 * No OpenGL. Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastGradientOpacityNodes_h
#define vtkTiledRayCastGradientOpacityNodes_h

class vtkVolumeProperty;

class vtkTiledRayCastGradientOpacityNodes
{
public:
  /**
   * Fills every member for this property and the mapper's blend mode.
   */
  void Compute(vtkVolumeProperty* property, int blendMode);

  static constexpr int MaximumNodes = 64;
  static constexpr int SamplesPerCurvedInterval = 16;
  bool Enabled = false;
  int NumberOfNodes = 0;
  float Nodes[MaximumNodes][2] = {}; // (gradient magnitude, value), increasing magnitude
  int Clamping = 1;                  // outside the nodes: the end values, or 0
  bool Approximated = false;
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastGradientOpacityNodes.h
