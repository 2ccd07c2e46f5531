//TRC::Version
//============================================================================
// TiledRayCast: one ray-casting pass over a tile. Every active ray walks up to
// in_tetsPerPass tets (0: no limit) from its tet to the neighbour across the
// face it leaves through, integrating each segment, until it leaves the mesh
// (TRC_WAITING: it may re-enter at a deeper boundary layer), reaches opaque
// geometry or the far plane, or becomes opaque. Ping-pong: the state is read
// from one pair of textures and written to the other; rays that are not active
// are copied unchanged, so that every pixel of the tile is written (the state,
// colour and entry textures always flip together).
//============================================================================
//TRC::Common::Dec
//TRC::RayTargets::Dec
//TRC::Layout::Dec
//TRC::Integration::Dec
//TRC::Walk::Dec

uniform int in_tetsPerPass;
// With no limit per pass, the most steps one ray may take in one pass (more than any ray can
// need: every tet once, plus the stalled steps allowed).
uniform int in_maximumSteps;

void main()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 state = texelFetch(in_state, pixel, 0);
  vec4 color = texelFetch(in_color, pixel, 0);
  fragOutput0 = state;
  fragOutput1 = color;
  fragOutput2 = texelFetch(in_entry, pixel, 0);
  if (trcStatus(state) != TRC_ACTIVE)
  {
    return;
  }

  TrcRay ray = trcPixelRay(gl_FragCoord.xy);
  uint tet = trcStateTet(state);
  float lambda = state.y;
  int entry = trcEntryFace(state);
  int stalls = trcStalls(state);
  int steps = 0;
  int maximumSteps = in_tetsPerPass == 0 ? in_maximumSteps : in_tetsPerPass;
  int status = trcWalk(ray, maximumSteps, tet, lambda, entry, stalls, color, steps);
  fragOutput0 = trcPackState(tet, lambda, status, entry, status == TRC_ACTIVE ? stalls : 0);
  fragOutput1 = color;
}
