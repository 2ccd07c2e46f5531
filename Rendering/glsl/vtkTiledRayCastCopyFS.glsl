//TRC::Version
//============================================================================
// TiledRayCast: copies the ray state and colour to the other ping-pong pair.
// As the paper's Z-update pass, it also writes depth 0 for rays that are no
// longer active so that later passes over the tile skip them (early z), and
// depth 1 for the others.
//============================================================================
//TRC::Common::Dec
//TRC::RayTargets::Dec

uniform int in_markInactive;

void main()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 state = texelFetch(in_state, pixel, 0);
  fragOutput0 = state;
  fragOutput1 = texelFetch(in_color, pixel, 0);
  fragOutput2 = texelFetch(in_entry, pixel, 0);
  if (in_markInactive != 0)
  {
    gl_FragDepth = trcStatus(state) == TRC_ACTIVE ? 1.0 : 0.0;
  }
  else
  {
    gl_FragDepth = gl_FragCoord.z;
  }
}
