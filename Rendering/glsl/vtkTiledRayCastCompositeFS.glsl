//TRC::Version
//============================================================================
// TiledRayCast: blends the volume's premultiplied colour over what the render
// window holds (blend function ONE, ONE_MINUS_SRC_ALPHA), pixels whose ray
// never entered the mesh left alone. In the compute pipeline (TRC_ENTRY_LIST)
// in_color is the traversal's colour image, zero where no ray entered, which
// the blend leaves alone by itself.
//============================================================================
//TRC::Common::Dec

#ifndef TRC_ENTRY_LIST
uniform sampler2D in_state;
#endif
uniform sampler2D in_color;
// Lower-left corner of the viewport in the window.
uniform vec2 in_viewportOrigin;

layout(location = 0) out vec4 fragOutput0;

void main()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy - in_viewportOrigin);
#ifndef TRC_ENTRY_LIST
  if (trcStatus(texelFetch(in_state, pixel, 0)) == TRC_MISS)
  {
    discard;
  }
#endif
  fragOutput0 = texelFetch(in_color, pixel, 0);
}
