/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastWarnings.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastWarnings
 * @brief   the mapper's errors and its warnings about what it does not do as asked
 *
 * A message repeated every frame would flood the output of an interactive session: an error is
 * said once until another comes or a frame is drawn (ClearError()), and each warning once per
 * mapper, except the warning of a frame drawn with boundary layers missing, which is said every
 * time (each such frame is wrong, the next ones are not). All are the mapper's own (through its
 * vtkObject, so that observers of its ErrorEvent and WarningEvent see them).
 *
 * No OpenGL. Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastWarnings_h
#define vtkTiledRayCastWarnings_h

#include "vtkType.h" // For vtkIdType

#include <string> // For std::string

class vtkObject;
class vtkRenderer;
class vtkTiledRayCastGradientOpacityNodes;
class vtkTiledRayCastLighting;
class vtkVolume;

class vtkTiledRayCastWarnings
{
public:
  explicit vtkTiledRayCastWarnings(vtkObject* reporter)
    : Reporter(reporter)
  {
  }

  /**
   * Report `message` as an error, unless it is the last one reported.
   */
  void ReportError(const std::string& message);

  /**
   * A frame was drawn: the next error is reported, whatever it is.
   */
  void ClearError() { this->LastError.clear(); }

  /**
   * Whether the mapper draws this blend mode (vtkVolumeMapper's) in this pipeline; an error
   * when not.
   */
  bool CheckBlendMode(int blendMode, bool compute);

  /**
   * What shading and gradient opacity of this frame do not do as asked: positional lights lit
   * as directional ones, lights beyond the maximum, a sampled gradient opacity function, shaded
   * cell scalars.
   */
  void WarnLighting(const vtkTiledRayCastLighting& lighting,
    const vtkTiledRayCastGradientOpacityNodes& gradientOpacity, bool cellScalars);

  /**
   * Translucent polygonal geometry in the renderer, which is not composited with the volume.
   */
  void WarnTranslucentGeometry(vtkRenderer* ren, vtkVolume* vol);

  /**
   * After a frame of the compute pipeline: `raysStopped` rays reached the bound of steps in a
   * layer, `raysIncomplete` rays missed layers (the view asked for `entries` ray entries).
   */
  void WarnAfterFrame(vtkIdType raysStopped, vtkIdType raysIncomplete, vtkIdType entries);

private:
  vtkObject* Reporter;
  std::string LastError;
  bool WarnedTranslucentGeometry = false;
  bool WarnedPositionalLights = false;
  bool WarnedIgnoredLights = false;
  bool WarnedShadedCellScalars = false;
  bool WarnedGradientOpacity = false;
  bool WarnedStoppedRays = false;
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastWarnings.h
