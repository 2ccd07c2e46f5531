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

#ifdef TRC_PEEL_STAGE
// Taking part in VTK's dual depth peeling (vtkTiledRayCastVolumetricPeelRanges.glsl): the traversal's
// front colour is in_color, its back colour in_backColor, one ray per pixel of the pass's own
// textures. What goes where is what the pass's shader replacements make its image ray caster
// write: at stage 1 the back colour to draw buffer 0 and the front to 1 (both start cleared,
// blended with MAX); at stage 2 the back colour to 0 and the front under the front colour so
// far (lastFrontColorTex) to 1, with MAX blending; at stage 3 the colour to 0, blended over.
//TRC::VolumetricPeel::Dec
uniform sampler2D in_backColor;
#if TRC_PEEL_STAGE == 2
uniform sampler2D lastFrontColorTex;
#endif
#if TRC_PEEL_STAGE != 3
layout(location = 1) out vec4 fragOutput1;
#endif

void main()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  if (trcPeelPixelDone(pixel))
  {
    discard;
  }
  vec4 front = texelFetch(in_color, pixel, 0);
#if TRC_PEEL_STAGE == 3
  fragOutput0 = front;
#else
  fragOutput0 = texelFetch(in_backColor, pixel, 0);
#if TRC_PEEL_STAGE == 1
  fragOutput1 = front;
#else
  vec4 last = texelFetch(lastFrontColorTex, pixel, 0);
  fragOutput1 = vec4(last.rgb + (1.0 - last.a) * front.rgb, 1.0 - (1.0 - last.a) * (1.0 - front.a));
#endif
#endif
}
#else

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
#endif
