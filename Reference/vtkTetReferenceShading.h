/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetReferenceShading.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetReferenceShading
 * @brief   the reference renderer's shading and gradient opacity, in double (private)
 *
 * The model of docs/design.md ("Shading"), computed here without the mapper's code: the colour
 * c(s) of a tetrahedron seen along a ray becomes
 *
 *   c'(s) = c(s) (ka + kd sum_i D_i max(n.l_i, 0)) + ks sum_i S_i [n.l_i > 0] max(n.h_i, 0)^p
 *
 * (per channel), with the property's ambient, diffuse, specular and specular power of component
 * 0; for each light that is on, D_i and S_i its diffuse and specular colours times its
 * intensity, l_i the unit vector towards it (every light directional: a positional light shines
 * from its position towards its focal point), h_i = (l_i + v) / |l_i + v|; v the unit vector
 * from the ray towards the viewer; n = -grad s / |grad s| of the tetrahedron's linear field in
 * world coordinates (n = 0 where the gradient is zero: the ambient term alone); with two-sided
 * lighting n.l and n.h are taken in absolute value. Headlights point along the camera, camera
 * lights are placed by the camera's light transform, scene lights where they are.
 *
 * c' = scale c + offset along the whole segment a ray makes in a tetrahedron, so its emission
 * c' tau integrates to scale C + offset alpha (C, alpha: the unshaded segment's premultiplied
 * colour and opacity): Apply().
 *
 * Gradient opacity (docs/design.md, "Gradient opacity"): the property's gradient opacity
 * function of component 0 (when set and not disabled), evaluated by vtkPiecewiseFunction at the
 * magnitude of the tetrahedron's world gradient and clamped to [0, 1], scales its attenuation;
 * as for shading, the gradient is constant over a segment, and an attenuation scaled by k over a
 * length L integrates as the attenuation itself over k L: OpacityScale() scales the length.
 * Both apply to the composite blend mode only.
 */

#ifndef vtkTetReferenceShading_h
#define vtkTetReferenceShading_h

#include "vtkType.h" // For vtkIdType

#include <vector> // For std::vector

class vtkCamera;
class vtkLightCollection;
class vtkPiecewiseFunction;
class vtkTetReferenceMesh;
class vtkVolumeProperty;

class vtkTetReferenceShading
{
public:
  /**
   * Set up from the property (shading off when its Shade(0) is off; its gradient opacity), the
   * lights (none: the ambient term alone), the camera and the two-sided flag, for tetrahedra of
   * `mesh` (world coordinates). The mesh and the property's function are kept by reference.
   */
  void Initialize(vtkVolumeProperty* property, vtkLightCollection* lights, vtkCamera* camera,
    bool twoSided, const vtkTetReferenceMesh* mesh);

  bool GetEnabled() const { return this->Enabled; }
  bool GetGradientOpacityEnabled() const { return this->GradientOpacity != nullptr; }

  /**
   * Whether the property shades (component 0) or has a gradient opacity that is not disabled
   * and changes something (not 1 at every node with clamping on): what a scene refuses.
   */
  static bool DependsOnGradient(vtkVolumeProperty* property);

  /**
   * The factor of tetrahedron `tet`'s attenuation (1 without gradient opacity).
   */
  double OpacityScale(vtkIdType tet) const;

  /**
   * The gradient of tetrahedron `tet`'s linear scalar field in world coordinates (zero for cell
   * scalars and degenerate tetrahedra).
   */
  static void Gradient(const vtkTetReferenceMesh& mesh, vtkIdType tet, double gradient[3]);

  /**
   * The colour's scale and offset for tetrahedron `tet` seen along ray direction `d` (any
   * length, pointing away from the viewer).
   */
  void Factors(vtkIdType tet, const double d[3], double scale[3], double offset[3]) const;

  /**
   * Shades a segment's premultiplied colour `rgb` of opacity `alpha` in tetrahedron `tet`.
   */
  void Apply(vtkIdType tet, const double d[3], double alpha, double rgb[3]) const;

private:
  struct Light
  {
    double ToLight[3];
    double Diffuse[3];
    double Specular[3];
  };
  bool Enabled = false;
  bool TwoSided = true;
  double Ambient = 0.0;
  double Diffuse = 0.0;
  double Specular = 0.0;
  double SpecularPower = 1.0;
  std::vector<Light> Lights;
  const vtkTetReferenceMesh* Mesh = nullptr;
  vtkPiecewiseFunction* GradientOpacity = nullptr;
};

#endif
// VTK-HeaderTest-Exclude: vtkTetReferenceShading.h
