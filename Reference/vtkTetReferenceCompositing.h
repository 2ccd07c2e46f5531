/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetReferenceCompositing.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetReferenceCompositing
 * @brief   private: vtkTetReferenceRenderer's compositing, along a ray and over a background
 *
 * CompositeRay integrates the tetrahedra a ray crosses front to back (each segment exactly,
 * vtkTetRayIntegrator) into premultiplied RGBA. vtkTetReferenceCompositing.cxx also defines
 * vtkTetReferenceRenderer's public static image helpers (compositing the RGBA image over a
 * background, the 8-bit conversion, the emulation of vtkUnstructuredGridVolumeRayCastMapper's
 * display, the image comparison): see vtkTetReferenceRenderer.h for what each does.
 */

#ifndef vtkTetReferenceCompositing_h
#define vtkTetReferenceCompositing_h

#include "vtkTetReferenceRayCaster.h" // For vtkTetReferenceRayCaster::Hit

#include <vector> // For std::vector

class vtkTetRayIntegrator;
class vtkTetReferenceShading;

class vtkTetReferenceCompositing
{
public:
  /**
   * Front-to-back compositing of `hits` (sorted; those of `transparent` tetrahedra skipped) into
   * premultiplied RGBA; `unitLength` is the length of a unit of the ray parameter. Stops once
   * what lies behind can change no value. With `shading` (enabled), each segment's colour is
   * shaded for its tetrahedron seen along the ray's direction `d`, and its attenuation scaled by
   * the tetrahedron's gradient opacity.
   */
  static void CompositeRay(const std::vector<vtkTetReferenceRayCaster::Hit>& hits,
    const std::vector<unsigned char>& transparent, vtkTetRayIntegrator* integrator,
    double unitLength, double rgba[4], const vtkTetReferenceShading* shading = nullptr,
    const double d[3] = nullptr);
};

#endif
// VTK-HeaderTest-Exclude: vtkTetReferenceCompositing.h
