/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetReferenceBlending.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetReferenceBlending
 * @brief   the reference renderer's blend modes other than compositing (private)
 *
 * Maximum and minimum intensity, average intensity and additive blending of the tetrahedra a
 * ray crosses, in double, straight from the volume property's own functions (not from the
 * GPU's node list or the segment integrator): the extreme scalar of a linear segment is at one
 * of its ends; the integral of opacity(s) times the normalised scalar is split at the opacity
 * function's nodes and integrated by 3-point Gauss-Legendre quadrature on eight parts of each
 * piece (exact where opacity is linear: the product is quadratic). What each mode means is
 * vtkTiledRayCastVolumeMapper's (SetBlendModeTo...).
 */

#ifndef vtkTetReferenceBlending_h
#define vtkTetReferenceBlending_h

#include "vtkTetReferenceRayCaster.h" // For vtkTetReferenceRayCaster::Hit

#include <vector> // For std::vector

class vtkVolumeProperty;

class vtkTetReferenceBlending
{
public:
  struct Settings
  {
    int Mode = 0;                        // vtkVolumeMapper's blend mode, 1 to 4
    double ScalarRange[2] = { 0.0, 1.0 }; // normalises the scalar to [0, 1]
    double AverageRange[2] = { 0.0, 0.0 };
    vtkVolumeProperty* Property = nullptr;
  };

  /**
   * The premultiplied RGBA of one ray from its `hits` (those of `transparent` tetrahedra left
   * out); `unitLength` is the world length of a unit of the ray parameter.
   */
  static void BlendRay(const std::vector<vtkTetReferenceRayCaster::Hit>& hits,
    const std::vector<unsigned char>& transparent, const Settings& settings, double unitLength,
    double rgba[4]);
};

#endif
// VTK-HeaderTest-Exclude: vtkTetReferenceBlending.h
