//TRC::Version
//============================================================================
// TiledRayCast: counts pixels (with an occlusion query) whose ray status is
// one of the selected ones; writes nothing.
//============================================================================
//TRC::Common::Dec

uniform sampler2D in_state;
// Bit s set: count rays of status s.
uniform int in_statusMask;

layout(location = 0) out vec4 fragOutput0;

void main()
{
  int status = trcStatus(texelFetch(in_state, ivec2(gl_FragCoord.xy), 0));
  if (((in_statusMask >> status) & 1) == 0)
  {
    discard;
  }
  fragOutput0 = vec4(0.0);
}
