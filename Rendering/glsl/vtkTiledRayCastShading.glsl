//============================================================================
// TiledRayCast: shading (vtkVolumeProperty::ShadeOn), compiled in only when the
// property shades under composite blending: the unshaded walk is unchanged.
//
// Each tet's scalar field is linear, so its gradient, hence the normal, is the
// same along the whole segment a ray makes in it; lights are directional and
// the direction to the viewer is the ray's own. The shaded colour is then
//   c'(s) = scale * c(s) + offset
// with scale and offset constant over the segment (per channel):
//   scale  = ka + kd sum_i D_i max(n.l_i, 0)
//   offset = ks sum_i S_i [n.l_i > 0] max(n.h_i, 0)^p
// n = -grad s / |grad s| in world coordinates (0 for a zero gradient: ambient
// only), l_i towards light i, h_i the half vector of l_i and the viewer; with
// two-sided lighting n.l and n.h are taken in absolute value. Because scale and
// offset are constants, the segment's emission c' tau integrates to
//   C' = scale * C + offset * alpha
// exactly, whatever the integration that gave the unshaded C and alpha (docs/design.md,
// "Shading"). vtkTiledRayCastLighting computes the uniforms.
//============================================================================
const int TRC_MAXIMUM_LIGHTS = 8;
uniform int in_numberOfLights;
uniform vec3 in_lightToLight[TRC_MAXIMUM_LIGHTS]; // unit, world coordinates
uniform vec3 in_lightDiffuse[TRC_MAXIMUM_LIGHTS];
uniform vec3 in_lightSpecular[TRC_MAXIMUM_LIGHTS];
uniform vec4 in_material; // ambient, diffuse, specular, specular power
uniform int in_twoSidedLighting;
#ifndef TRC_GRADIENT_TO_WORLD
#define TRC_GRADIENT_TO_WORLD
// Object-space gradient to world coordinates: the inverse transpose of the volume matrix.
uniform mat3 in_gradientToWorld;
#endif

// The direction from a ray to the viewer, in world coordinates.
vec3 trcToViewer(TrcRay ray)
{
  return -normalize(in_objectToWorld * ray.dir);
}

// Scale and offset of the colour in a tet whose field has object-space gradient `gradient`.
void trcShadingFactors(vec3 gradient, vec3 toViewer, out vec3 scale, out vec3 offset)
{
  vec3 g = in_gradientToWorld * gradient;
  float magnitude = length(g);
  vec3 n = magnitude > 0.0 ? -g / magnitude : vec3(0.0);
  vec3 diffuse = vec3(0.0);
  vec3 specular = vec3(0.0);
  for (int i = 0; i < in_numberOfLights; ++i)
  {
    vec3 l = in_lightToLight[i];
    vec3 halfway = l + toViewer;
    float halfLength = length(halfway);
    float nl = dot(n, l);
    float nh = halfLength > 0.0 ? dot(n, halfway) / halfLength : 0.0;
    if (in_twoSidedLighting != 0)
    {
      nl = abs(nl);
      nh = abs(nh);
    }
    if (nl > 0.0)
    {
      diffuse += nl * in_lightDiffuse[i];
      // pow(0, p) is undefined in GLSL: no highlight where n.h is not positive.
      specular += (nh > 0.0 ? pow(nh, in_material.w) : 0.0) * in_lightSpecular[i];
    }
  }
  scale = vec3(in_material.x) + in_material.y * diffuse;
  offset = in_material.z * specular;
}

// Composite a segment integrated unshaded (premultiplied `segment`) in a tet whose field has
// object-space gradient `gradient`.
void trcCompositeShaded(vec4 segment, vec3 gradient, vec3 toViewer, inout vec4 color)
{
  if (!(segment.a > 0.0))
  {
    return;
  }
  vec3 scale;
  vec3 offset;
  trcShadingFactors(gradient, toViewer, scale, offset);
  color.rgb += (1.0 - color.a) * (scale * segment.rgb + offset * segment.a);
  color.a += (1.0 - color.a) * segment.a;
}
