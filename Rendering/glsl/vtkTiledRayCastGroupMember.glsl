//============================================================================
// TiledRayCast: what the traversal of overlapping volumes
// (vtkTiledRayCastGroupTraversalCS.glsl) needs of one volume, written with
// the names of the one-volume shaders. vtkTiledRayCastGroupTraversal appends
// this to a volume's own common, layout, integration and walk code and gives
// every trc*, Trc*, TRC_* and in_* name of the whole a suffix per volume
// (_v0, _v1, ...): each volume keeps its own mesh, transfer function, rays and
// uniforms, and the traversal calls trcMemberEvent_v1 and so on.
//
// A volume's state is one TrcMember, a global of the traversal per volume that
// only these functions and lines of the traversal written per volume touch:
// never indexed by a volume index that varies per ray, so that it stays in
// registers (NVIDIA's compiler puts an array indexed that way in local memory).
//============================================================================

// lastKey of a layer entered at the near plane (after every face key).
const uint TRC_MEMBER_NEAR_PLANE_KEY = 0xFFFFFFFEu;

// The volume on one ray: inside tet `tet` (entered through face `entry`, TRC_NO_FACE from the
// near plane), at lambda `from`, where its current span begins; or waiting for its next entry at
// entryLambda (pending), or neither (done). Lambda is the volume's own; mu = lambda - in_lambdaNear
// is the same for every volume at the same point (the volume matrices are affine).
//
// A span is where the volume's attenuation and colour are linear along the ray: within its tet,
// between two nodes of its transfer function (interval `node` to node + 1). It ends at
// spanEnd: the tet's exit (exitAt, through exitFace), or where the scalar reaches the next node.
// Over the span the attenuation is tau + tauRate (lambda - from) and the colour color +
// colorRate (lambda - from): a piece of the ray where several volumes are inside sums theirs
// with no read of the transfer function, and only the volume whose span ends moves on.
struct TrcMember
{
  float lambdaMin; // where its ray begins and ends (trcMemberRay makes the rest again)
  float lambdaMax;
  bool inside;
  bool pending;
  uint tet;
  int entry;
  float from;
  float exitAt;
  int exitFace;
  float scalar;     // the scalar at `from`
  float scalarRate; // per unit lambda, in this tet
  int node; // the span's interval: the transfer function's node at or below the scalar (-1 below)
  float spanEnd;
  float tau;
  float tauRate;
  vec3 color;
  vec3 colorRate;
  int layerSteps;
  int stalls;
  float entryLambda;
  uint entryKey;
  bool entryNear;
  float lastLambda; // the layer entered last, for the peeling rules
  uint lastKey;
};

// The volume's ray through a pixel, before its first entry; every word defined before it is read
// (a volume that never enters keeps these).
void trcMemberStart(vec2 fragCoord, out TrcMember s)
{
  s.lambdaMax = trcPixelRay(fragCoord).lambdaMax;
  // A group takes no volume with clipping planes (vtkTiledRayCastVolumeGroup::Refusal): said
  // here, the walk's clipping test folds away and the state holds one word less.
  s.lambdaMin = -3.4e38;
  s.inside = false;
  s.pending = false;
  s.tet = 0u;
  s.entry = TRC_NO_FACE;
  s.from = 0.0;
  s.exitAt = 0.0;
  s.exitFace = 0;
  s.scalar = 0.0;
  s.scalarRate = 0.0;
  s.node = -2; // none yet
  s.spanEnd = 0.0;
  s.tau = 0.0;
  s.tauRate = 0.0;
  s.color = vec3(0.0);
  s.colorRate = vec3(0.0);
  s.layerSteps = 0;
  s.stalls = 0;
  s.entryLambda = 0.0;
  s.entryKey = 0u;
  s.entryNear = false;
  s.lastLambda = 0.0;
  s.lastKey = 0u;
}

// The volume's ray through the traversal's pixel (groupRayPixel), between its bounds: made again
// from the volume's uniforms where it is needed (a dozen multiply-adds), so that each volume's
// state holds two words of it instead of eleven.
TrcRay trcMemberRay(TrcMember s)
{
  TrcRay ray = trcPixelRayGeometry(groupRayPixel);
  ray.lambdaMin = s.lambdaMin;
  ray.lambdaMax = s.lambdaMax;
  return ray;
}

// The world length of a unit of lambda on the traversal's pixel's ray (the same for every volume
// of the group: mu = lambda - lambdaNear is).
float trcMemberWorldScale()
{
  return trcPixelRayGeometry(groupRayPixel).worldScale;
}

// trcFindNode(s), where `hint` is likely to be the answer (the node of the volume's last span: a
// span seldom crosses a node, so the next starts there): checked with two independent reads
// instead of a binary search's dependent ones, else searched.
int trcMemberFindNode(float s, int hint)
{
  int n = in_transferFunctionNodes;
  bool above = hint < 0 || trcNodeScalar(max(hint, 0)) <= s;
  bool under = hint + 1 >= n || s < trcNodeScalar(min(hint + 1, n - 1));
  return hint >= -1 && hint < n && above && under ? hint : trcFindNode(s);
}

// The span from s.from, where the scalar is s.scalar (the interval it goes into: going down from
// a node, the one below it), up to the next node or the tet's exit. A tet touching a non-finite
// scalar is transparent, as in trcIntegrate.
void trcMemberSpan(inout TrcMember s)
{
  float s0 = s.scalar;
  float r = s.scalarRate;
  s.spanEnd = s.exitAt;
  if (isnan(s0) || isinf(s0) || isnan(r) || isinf(r))
  {
    s.tau = 0.0;
    s.tauRate = 0.0;
    s.color = vec3(0.0);
    s.colorRate = vec3(0.0);
    return;
  }
  int n = in_transferFunctionNodes;
  int lo = trcMemberFindNode(s0, s.node);
  while (r < 0.0 && lo >= 0 && trcNodeScalar(lo) >= s0)
  {
    --lo;
  }
  s.node = lo;
  int first = clamp(lo, 0, n - 1);
  int second = lo < 0 ? first : min(lo + 1, n - 1);
  // A node's scalar and attenuation are one texel, its colour the next.
  vec2 a = texelFetch(in_transferFunction, 2 * first).xy;
  vec2 b = texelFetch(in_transferFunction, 2 * second).xy;
  vec3 ca = texelFetch(in_transferFunction, 2 * first + 1).rgb;
  vec3 cb = texelFetch(in_transferFunction, 2 * second + 1).rgb;
  float ds = b.x - a.x;
  float w = ds > 0.0 ? clamp((s0 - a.x) / ds, 0.0, 1.0) : 1.0;
  float wRate = ds > 0.0 ? r / ds : 0.0;
  s.tau = mix(a.y, b.y, w);
  s.tauRate = (b.y - a.y) * wRate;
  s.color = mix(ca, cb, w);
  s.colorRate = (cb - ca) * wRate;
  // Where the scalar reaches the interval's far node (going up, the node above; down, the one
  // below), if before the exit.
  bool up = r > 0.0 && lo < n - 1;
  bool down = r < 0.0 && lo >= 0;
  if (up || down)
  {
    float toward = up ? b.x : a.x;
    s.spanEnd = min(s.exitAt, s.from + max((toward - s0) / r, 0.0));
  }
}

// The volume at s.from in tet s.tet (entered through s.entry): where the ray leaves it, its
// scalar along the ray, and its first span there.
void trcMemberEnterTet(inout TrcMember s)
{
  TrcTet t;
  trcLoadTet(s.tet, t);
  TrcRay ray = trcMemberRay(s);
  float exitStep = trcExitStep(t, ray, s.from, s.entry, s.exitFace);
  s.exitAt = s.from + max(exitStep, 0.0);
  s.stalls = s.exitAt > s.from ? 0 : s.stalls + 1;
  s.scalar = dot(t.field.xyz, ray.origin + s.from * ray.dir) + t.field.w;
  s.scalarRate = dot(t.field.xyz, ray.dir);
  trcMemberSpan(s);
}

// The volume's event: its span ends at a node (the next span, in the same tet), it enters the
// layer of its pending entry, or it leaves its tet, into the neighbour behind its exit face.
// False where it leaves its layer there (the ray left the volume, or its visible part, stalled,
// or took maximumSteps in the layer): the traversal then takes its next entry.
bool trcMemberEvent(inout TrcMember s, int maximumSteps, inout int steps, inout uint layers,
  inout bool startedNear, inout bool stopped)
{
  if (s.inside && s.spanEnd < s.exitAt)
  {
    // The scalar reaches a node: exactly its value from here, the interval beyond it next.
    bool up = s.scalarRate > 0.0;
    int crossed = up ? s.node + 1 : s.node;
    s.scalar = trcNodeScalar(crossed);
    s.from = s.spanEnd;
    s.node = crossed;
    trcMemberSpan(s);
    return true;
  }
  if (s.inside)
  {
    s.from = s.exitAt;
    uvec4 words = trcLoadNeighborWords(s.tet);
    uint next = trcNeighborTet(words, s.exitFace);
#ifdef TRC_SKIP_EMPTY_SPACE
    bool leaves = next == TRC_NO_NEIGHBOR || !trcTetVisible(next);
#else
    bool leaves = next == TRC_NO_NEIGHBOR;
#endif
    if (leaves || s.stalls > TRC_MAXIMUM_STALLS || s.layerSteps >= maximumSteps)
    {
      stopped = stopped || s.layerSteps >= maximumSteps;
      s.inside = false;
      return false;
    }
    s.entry = trcNeighborFace(words, s.exitFace);
    s.tet = next;
    ++s.layerSteps;
  }
  else
  {
    s.pending = false;
    s.inside = true;
    ++layers;
    startedNear = startedNear || s.entryNear;
    s.lastLambda = s.entryLambda;
    s.lastKey = s.entryNear ? TRC_MEMBER_NEAR_PLANE_KEY : s.entryKey;
    s.tet = s.entryKey >> 2u;
    s.entry = s.entryNear ? TRC_NO_FACE : int(s.entryKey & 3u);
    s.from = s.entryLambda;
    s.layerSteps = 1;
    s.stalls = 0;
  }
  ++steps;
  trcMemberEnterTet(s);
  return true;
}

// The volume on to `lambda` within its span (where the ray is), its span's values with it.
void trcMemberAdvance(inout TrcMember s, float lambda)
{
  float d = lambda - s.from;
  if (d > 0.0)
  {
    s.scalar += s.scalarRate * d;
    s.tau += s.tauRate * d;
    s.color += s.colorRate * d;
    s.from = lambda;
  }
}

// The volume alone on the ray (inside, every other volume ahead of it or done) up to mu = bound
// (the nearest entry of another): its own walk from where it is, the one-volume traversal's
// loop and arithmetic, so that it is integrated as when it is drawn alone. False where the ray
// ends (opaque, or at the end of the volume's ray). Else it is either inside at the bound (its
// span there found) or out of its layer at s.from (the traversal takes its next entry).
bool trcMemberWalk(inout TrcMember s, float bound, int maximumSteps, inout vec4 color,
  inout int steps, inout bool stopped)
{
  TrcRay ray = trcMemberRay(s);
  float end = bound + in_lambdaNear;
  bool clamped = end < ray.lambdaMax;
  if (clamped && !(end > s.from))
  {
    return true; // at the bound already (within rounding): nothing to walk
  }
  ray.lambdaMax = min(ray.lambdaMax, end);
  float lambda = s.from;
  int before = steps;
  int status =
    trcWalk(ray, max(maximumSteps - s.layerSteps + 1, 1), s.tet, lambda, s.entry, s.stalls, color, steps);
  // The tet it was in was counted when it entered it.
  int taken = steps - before - 1;
  steps -= 1;
  s.layerSteps += taken;
  s.from = lambda;
  if (status == TRC_DONE_DEPTH && clamped)
  {
    trcMemberEnterTet(s);
    return true;
  }
  if (status == TRC_WAITING || status == TRC_ACTIVE)
  {
    stopped = stopped || status == TRC_ACTIVE;
    s.inside = false;
    return true;
  }
  return false;
}

// The volume's share of a piece of the ray from lambda a to b (both within its span), where its
// attenuation and colour are linear: attenuation ta at a to tb at b, emission (attenuation
// times colour) e0 + e1 v + e2 v^2 for v from 0 to 1 over the piece (trcCompositeMixture).
void trcMemberPart(TrcMember s, float a, float b, inout float ta, inout float tb,
  inout vec3 e0, inout vec3 e1, inout vec3 e2)
{
  float t0 = max(s.tau + s.tauRate * (a - s.from), 0.0);
  float t1 = max(s.tau + s.tauRate * (b - s.from), 0.0);
  vec3 c0 = s.color + s.colorRate * (a - s.from);
  vec3 c1 = s.color + s.colorRate * (b - s.from);
  ta += t0;
  tb += t1;
  e0 += t0 * c0;
  e1 += t0 * (c1 - c0) + (t1 - t0) * c0;
  e2 += (t1 - t0) * (c1 - c0);
}
