//TRC::Version
//============================================================================
// TiledRayCast: blends the volume's premultiplied colour over what the render
// window holds (blend function ONE, ONE_MINUS_SRC_ALPHA), pixels whose ray
// never entered the mesh left alone.
//============================================================================
//TRC::Common::Dec

uniform sampler2D in_state;
uniform sampler2D in_color;
// Lower-left corner of the viewport in the window.
uniform vec2 in_viewportOrigin;

layout(location = 0) out vec4 fragOutput0;

void main()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy - in_viewportOrigin);
  if (trcStatus(texelFetch(in_state, pixel, 0)) == TRC_MISS)
  {
    discard;
  }
  fragOutput0 = texelFetch(in_color, pixel, 0);
}
