//============================================================================
// TiledRayCast: gradient opacity (vtkVolumeProperty::SetGradientOpacity),
// compiled in only when the property has one that changes something, under
// composite blending: the walk without it is unchanged.
//
// A tet's field is linear: the magnitude of its gradient, in scalar units per
// world unit, is the same along the whole segment, and so is the scale k of
// the attenuation there. An attenuation k tau over a length L integrates as tau
// over k L (the scalar goes from the same front to the same back value), so the
// walk scales the segment's length: exact for every integration, as the
// integration is at that length (docs/design.md, "Gradient opacity").
// vtkTiledRayCastGradientOpacityNodes computes the uniforms.
//============================================================================
#ifndef TRC_GRADIENT_TO_WORLD
#define TRC_GRADIENT_TO_WORLD
// Object-space gradient to world coordinates: the inverse transpose of the volume matrix.
uniform mat3 in_gradientToWorld;
#endif
const int TRC_MAXIMUM_GRADIENT_OPACITY_NODES = 64;
uniform int in_gradientOpacityNodes;
uniform vec2 in_gradientOpacity[TRC_MAXIMUM_GRADIENT_OPACITY_NODES]; // (magnitude, value)
uniform int in_gradientOpacityClamping;

// The factor of the attenuation in a tet whose field has object-space gradient `gradient`.
float trcGradientOpacity(vec3 gradient)
{
  float magnitude = length(in_gradientToWorld * gradient);
  int last = in_gradientOpacityNodes - 1;
  float value;
  if (magnitude < in_gradientOpacity[0].x || magnitude > in_gradientOpacity[last].x)
  {
    // Outside the function's range: its end value when it clamps, 0 when it does not.
    float end = magnitude < in_gradientOpacity[0].x ? in_gradientOpacity[0].y
                                                   : in_gradientOpacity[last].y;
    value = in_gradientOpacityClamping != 0 ? end : 0.0;
  }
  else
  {
    int i = 1;
    while (i < last && in_gradientOpacity[i].x < magnitude)
    {
      ++i;
    }
    vec2 a = in_gradientOpacity[i - 1];
    vec2 b = in_gradientOpacity[i];
    float w = b.x > a.x ? (magnitude - a.x) / (b.x - a.x) : 1.0;
    value = last == 0 ? a.y : mix(a.y, b.y, clamp(w, 0.0, 1.0));
  }
  return clamp(value, 0.0, 1.0);
}
