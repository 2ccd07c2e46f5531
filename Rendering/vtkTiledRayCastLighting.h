/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastLighting.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastLighting
 * @brief   the renderer's lights and the property's material as the shaders' uniforms
 *
 * Shading (vtkVolumeProperty::ShadeOn, docs/design.md "Shading") is computed per segment by
 * vtkTiledRayCastShading.glsl from these values, recomputed every frame (the camera moves
 * headlights and camera lights): the material of component 0, and for each light that is on,
 * its unit direction towards the light in world coordinates and its diffuse and specular
 * colours times its intensity. Every light is directional: a positional light (spot or point)
 * shines from its position towards its focal point, without attenuation or cone (counted in
 * NumberOfPositionalLights, for the mapper's warning). The shaders receive the object-space
 * gradient of each tet's field; GradientToWorld (the inverse transpose of the volume matrix's
 * linear part) takes it to world coordinates.
 *
 * No OpenGL. Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastLighting_h
#define vtkTiledRayCastLighting_h

class vtkRenderer;
class vtkVolume;

class vtkTiledRayCastLighting
{
public:
  /**
   * Fills every member for this renderer's lights and camera, this volume's property and
   * matrix, and the mapper's blend mode: Enabled when the property shades component 0 under
   * composite blending (VTK's volume mappers shade nothing else). GradientToWorld is filled
   * whether or not (gradient opacity needs it too).
   */
  void Compute(vtkRenderer* renderer, vtkVolume* volume, int blendMode);

  static constexpr int MaximumLights = 8;
  bool Enabled = false;
  float Material[4] = {};                     // ambient, diffuse, specular, specular power
  int NumberOfLights = 0;                     // those below, at most MaximumLights
  float ToLight[MaximumLights][3] = {};       // unit, world coordinates
  float Diffuse[MaximumLights][3] = {};       // colour times intensity
  float Specular[MaximumLights][3] = {};      // idem
  int TwoSided = 1;                           // the renderer's two-sided lighting
  float GradientToWorld[9] = {};              // column-major, as GLSL's mat3
  int NumberOfPositionalLights = 0;           // lit as directional lights
  int NumberOfIgnoredLights = 0;              // beyond MaximumLights
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastLighting.h
