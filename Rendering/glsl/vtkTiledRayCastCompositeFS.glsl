//TRC::Version
//============================================================================
// TiledRayCast: blends the volume's premultiplied colour over what the render
// window holds (blend function ONE, ONE_MINUS_SRC_ALPHA), pixels whose ray
// never entered the mesh left alone. In the compute pipeline (TRC_ENTRY_LIST)
// in_color is the traversal's colour image, zero where no ray entered, which
// the blend leaves alone by itself.
//
// At an image sample distance above 1 there are fewer rays than pixels: each
// pixel takes the bilinear interpolation of the four rays around it (rays at
// the centres of an image of in_imageSize over the viewport), a ray that never
// entered the mesh counting as transparent (premultiplied colours interpolate
// as they composite).
//============================================================================
//TRC::Common::Dec

#ifndef TRC_ENTRY_LIST
uniform sampler2D in_state;
#endif
uniform sampler2D in_color;
// Lower-left corner of the viewport in the window.
uniform vec2 in_viewportOrigin;
// Rays per viewport pixel along x and y (1: one ray per pixel), and the rays' image size.
uniform vec2 in_sampleScale;
uniform ivec2 in_imageSize;

layout(location = 0) out vec4 fragOutput0;

// The colour of ray `pixel` (clamped to the image), transparent where it missed the mesh.
vec4 trcRayColor(ivec2 pixel)
{
  pixel = clamp(pixel, ivec2(0), in_imageSize - 1);
#ifndef TRC_ENTRY_LIST
  if (trcStatus(texelFetch(in_state, pixel, 0)) == TRC_MISS)
  {
    return vec4(0.0);
  }
#endif
  return texelFetch(in_color, pixel, 0);
}

void main()
{
  vec2 here = gl_FragCoord.xy - in_viewportOrigin;
  if (in_sampleScale == vec2(1.0))
  {
    ivec2 pixel = ivec2(here);
#ifndef TRC_ENTRY_LIST
    if (trcStatus(texelFetch(in_state, pixel, 0)) == TRC_MISS)
    {
      discard;
    }
#endif
    fragOutput0 = texelFetch(in_color, pixel, 0);
    return;
  }
  vec2 at = here * in_sampleScale - 0.5;
  ivec2 corner = ivec2(floor(at));
  vec2 f = at - vec2(corner);
  vec4 below = mix(trcRayColor(corner), trcRayColor(corner + ivec2(1, 0)), f.x);
  vec4 above = mix(trcRayColor(corner + ivec2(0, 1)), trcRayColor(corner + ivec2(1, 1)), f.x);
  fragOutput0 = mix(below, above, f.y);
}
