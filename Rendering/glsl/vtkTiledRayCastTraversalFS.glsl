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
//TRC::Layout::Dec
//TRC::Integration::Dec

uniform sampler2D in_state;
uniform sampler2D in_color;
uniform sampler2D in_entry;
uniform int in_tetsPerPass;
// With no limit per pass, the most steps one ray may take in one pass (more than any ray can
// need: every tet once, plus the stalled steps allowed).
uniform int in_maximumSteps;

// Steps in a row that leave a ray where it is: beyond this, the ray is caught between
// degenerate tets and leaves the mesh where it stands (it may re-enter at the next layer).
const int TRC_MAXIMUM_STALLS = 64;

layout(location = 0) out vec4 fragOutput0;
layout(location = 1) out vec4 fragOutput1;
layout(location = 2) out vec4 fragOutput2;

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
  uint previous = TRC_NO_NEIGHBOR;
  int status = TRC_ACTIVE;
  int stalls = trcStalls(state);
  int steps = 0;
  int maximumSteps = in_tetsPerPass == 0 ? in_maximumSteps : in_tetsPerPass;
  while (status == TRC_ACTIVE && steps < maximumSteps)
  {
    ++steps;
    vec3 p[4];
    vec3 n[4];
    vec4 field;
    trcLoadTet(tet, p, n, field);
    uvec4 neighbors;
    ivec4 neighborFaces;
    trcLoadNeighbors(tet, neighbors, neighborFaces);
    if (entry == TRC_FACE_FROM_PREVIOUS)
    {
      // Layouts that store no entry face: the face shared with the tet we came from.
      entry = TRC_NO_FACE;
      for (int f = 0; f < 4; ++f)
      {
        entry = neighbors[f] == previous ? f : entry;
      }
    }

    // The exit face: the nearest plane the ray leaves through, never the entry face.
    // Distances are measured from the ray's current point, next to the tet, not from its
    // origin on the near plane: in a flat tet, planes a few float steps apart at lambda ~ 0.5
    // are then told apart (the wrong one skips a tet).
    vec3 here = ray.origin + lambda * ray.dir;
    float exitStep = 3.4e38;
    int exitFace = -1;
    float steepest = -3.4e38;
    int steepestFace = 0;
    for (int f = 0; f < 4; ++f)
    {
      if (f == entry)
      {
        continue;
      }
      float den = dot(n[f], ray.dir);
      if (den > steepest)
      {
        steepest = den;
        steepestFace = f;
      }
      if (den > 0.0)
      {
        float step = dot(p[trcFacePoints[f].x] - here, n[f]) / den;
        if (step < exitStep)
        {
          exitStep = step;
          exitFace = f;
        }
      }
    }
    if (exitFace < 0)
    {
      // No face faces away from the ray (a degenerate tet, or a ray inside a
      // face's plane): leave through the most favourable face without moving.
      exitFace = steepestFace;
      exitStep = 0.0;
    }
    float exitLambda = lambda + max(exitStep, 0.0);
    stalls = exitLambda > lambda ? 0 : stalls + 1;

    bool stopped = exitLambda >= ray.lambdaMax;
    float endLambda = min(exitLambda, ray.lambdaMax);
    float sFront = dot(field.xyz, ray.origin + lambda * ray.dir) + field.w;
    float sBack = dot(field.xyz, ray.origin + endLambda * ray.dir) + field.w;
    trcIntegrate(sFront, sBack, (endLambda - lambda) * ray.worldScale, color);
    lambda = endLambda;

    if (color.a >= in_earlyTerminationOpacity)
    {
      status = TRC_DONE_OPAQUE;
    }
    else if (stopped)
    {
      status = TRC_DONE_DEPTH;
    }
    else if (neighbors[exitFace] == TRC_NO_NEIGHBOR || stalls > TRC_MAXIMUM_STALLS)
    {
      status = TRC_WAITING;
    }
    else
    {
      previous = tet;
      tet = neighbors[exitFace];
      entry = neighborFaces[exitFace];
    }
  }
  if (status == TRC_ACTIVE && entry == TRC_FACE_FROM_PREVIOUS)
  {
    // The pass ends inside the mesh: resolve the entry face now, the next pass
    // does not know where the ray came from.
    uvec4 neighbors;
    ivec4 neighborFaces;
    trcLoadNeighbors(tet, neighbors, neighborFaces);
    entry = TRC_NO_FACE;
    for (int f = 0; f < 4; ++f)
    {
      entry = neighbors[f] == previous ? f : entry;
    }
  }
  fragOutput0 = trcPackState(tet, lambda, status, entry, status == TRC_ACTIVE ? stalls : 0);
  fragOutput1 = color;
}
