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
// near plane) from lambda `from` to its exit `exitAt` through exitFace (the tet's field and
// neighbour words read), or waiting for its next entry at entryLambda (pending), or neither
// (done). Lambda is the volume's own; mu = lambda - lambdaNear is the same for every volume at
// the same point (the volume matrices are affine).
struct TrcMember
{
  TrcRay ray;
  float lambdaNear;
  bool inside;
  bool pending;
  uint tet;
  int entry;
  float from;
  float exitAt;
  int exitFace;
  vec4 field;
  uvec4 words;
  int layerSteps;
  int stalls;
  float entryLambda;
  uint entryKey;
  bool entryNear;
  float lastLambda; // the layer entered last, for the peeling rules
  uint lastKey;
  int node; // the transfer function's node at or below its scalar where the last piece ended
};

// The volume's ray through a pixel, before its first entry; every word defined before it is read
// (a volume that never enters keeps these).
void trcMemberStart(vec2 fragCoord, out TrcMember s)
{
  s.ray = trcPixelRay(fragCoord);
  // A group takes no volume with clipping planes (vtkTiledRayCastVolumeGroup::Refusal): said
  // here, the walk's clipping test folds away and the state holds one word less.
  s.ray.lambdaMin = -3.4e38;
  s.lambdaNear = in_lambdaNear;
  s.inside = false;
  s.pending = false;
  s.tet = 0u;
  s.entry = TRC_NO_FACE;
  s.from = 0.0;
  s.exitAt = 0.0;
  s.exitFace = 0;
  s.field = vec4(0.0);
  s.words = uvec4(0u);
  s.layerSteps = 0;
  s.stalls = 0;
  s.entryLambda = 0.0;
  s.entryKey = 0u;
  s.entryNear = false;
  s.lastLambda = 0.0;
  s.lastKey = 0u;
  s.node = -2; // none yet
}

// Where the ray leaves its tet from s.from (the walk's arithmetic): s.exitAt and s.exitFace, the
// tet's field and neighbour words.
void trcMemberExit(inout TrcMember s)
{
  TrcTet t;
  trcLoadTet(s.tet, t);
  s.words = trcLoadNeighborWords(s.tet);
  float exitStep = trcExitStep(t, s.ray, s.from, s.entry, s.exitFace);
  s.field = t.field;
  s.exitAt = s.from + max(exitStep, 0.0);
  s.stalls = s.exitAt > s.from ? 0 : s.stalls + 1;
}

// The volume's event: it enters the layer of its pending entry, or leaves its tet, into the
// neighbour behind its exit face. False where it leaves its layer there (the ray left the
// volume, or its visible part, stalled, or took maximumSteps in the layer): the traversal then
// takes its next entry. The exit of the tet it is in is read once, for both cases.
bool trcMemberEvent(inout TrcMember s, int maximumSteps, inout int steps, inout uint layers,
  inout bool startedNear, inout bool stopped)
{
  if (s.inside)
  {
    s.from = s.exitAt;
    uint next = trcNeighborTet(s.words, s.exitFace);
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
    s.entry = trcNeighborFace(s.words, s.exitFace);
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
  trcMemberExit(s);
  return true;
}

// The volume alone on the ray (inside, every other volume ahead of it or done) up to mu = bound
// (the nearest entry of another): its own walk from where it is, the one-volume traversal's
// loop and arithmetic, so that it is integrated as when it is drawn alone. False where the ray
// ends (opaque, or at the end of the volume's ray). Else it is either inside at the bound (its
// exit read) or out of its layer at s.from (the traversal takes its next entry).
bool trcMemberWalk(inout TrcMember s, float bound, int maximumSteps, inout vec4 color,
  inout int steps, inout bool stopped)
{
  TrcRay ray = s.ray;
  float end = bound + s.lambdaNear;
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
  // The tet it was in was counted when its exit was read.
  int taken = steps - before - 1;
  steps -= 1;
  s.layerSteps += taken;
  s.from = lambda;
  if (status == TRC_DONE_DEPTH && clamped)
  {
    trcMemberExit(s);
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

// A piece of the ray up to mu = end where the volumes inside are integrated together: the
// volume's scalar at both ends (from where it is to `end`, or to its own exit exactly when the
// event is that), and it moves there. False where it is not inside.
bool trcMemberPiece(inout TrcMember s, bool toExit, float end, out float sf, out float sb)
{
  sf = 0.0;
  sb = 0.0;
  if (!s.inside)
  {
    return false;
  }
  float to = toExit ? s.exitAt : min(s.exitAt, end + s.lambdaNear);
  to = max(to, s.from);
  sf = dot(s.field.xyz, s.ray.origin + s.from * s.ray.dir) + s.field.w;
  sb = dot(s.field.xyz, s.ray.origin + to * s.ray.dir) + s.field.w;
  s.from = to;
  // A tet touching a non-finite scalar is transparent, as in trcIntegrate.
  return !isnan(sf) && !isnan(sb) && !isinf(sf) && !isinf(sb);
}

int trcMemberNodes()
{
  return in_transferFunctionNodes;
}

// trcFindNode(s), where `hint` is likely to be the answer (the node where the volume's last piece
// ended: a piece seldom crosses a node, so the next starts there): checked with two independent
// reads instead of a binary search's dependent ones, else searched.
int trcMemberFindNode(float s, int hint)
{
  int n = in_transferFunctionNodes;
  bool above = hint < 0 || trcNodeScalar(max(hint, 0)) <= s;
  bool under = hint + 1 >= n || s < trcNodeScalar(min(hint + 1, n - 1));
  return hint >= -1 && hint < n && above && under ? hint : trcFindNode(s);
}

// The mixture of overlapping volumes (trcGroupMixture): over a piece where the volume's scalar
// goes linearly from sf to sb, u from 0 to 1, `next` is the next node its scalar crosses
// (going up, the first above sf; going down, the last below; constant, the node at or below).
int trcMemberFirstNode(float sf, float sb, int hint)
{
  int below = trcMemberFindNode(sf, hint);
  if (sb > sf)
  {
    return below + 1;
  }
  return sb < sf && below >= 0 && trcNodeScalar(below) >= sf ? below - 1 : below;
}

// Where on the piece (u) the scalar crosses node `next`, or 1.
float trcMemberCrossing(bool used, float sf, float sb, int next)
{
  float ds = sb - sf;
  bool crosses = (ds > 0.0 && next < in_transferFunctionNodes) || (ds < 0.0 && next >= 0);
  return used && crosses ? (trcNodeScalar(next) - sf) / ds : 1.0;
}

// The volume's share of the part [u0, u1] of the piece, where its attenuation and colour are
// linear: attenuation ta at u0 to tb at u1, emission (attenuation times colour)
// e0 + e1 v + e2 v^2 for v from 0 to 1 over the part. Both ends lie between the same two nodes:
// they are read once (trcEvaluate's cases: below the first node or from the last on, that
// node's values).
void trcMemberMixturePart(bool used, float sf, float sb, int next, float u0, float u1,
  inout float ta, inout float tb, inout vec3 e0, inout vec3 e1, inout vec3 e2)
{
  if (!used)
  {
    return;
  }
  float ds = sb - sf;
  int below = ds > 0.0 ? next - 1 : next;
  int first = clamp(below, 0, in_transferFunctionNodes - 1);
  int second = below < 0 ? first : min(below + 1, in_transferFunctionNodes - 1);
  float s0 = trcNodeScalar(first);
  float s1 = trcNodeScalar(second);
  vec3 n0;
  vec3 n1;
  float t0;
  float t1;
  trcNode(first, n0, t0);
  trcNode(second, n1, t1);
  float w0 = s1 > s0 ? clamp((sf + u0 * ds - s0) / (s1 - s0), 0.0, 1.0) : 1.0;
  float w1 = s1 > s0 ? clamp((sf + u1 * ds - s0) / (s1 - s0), 0.0, 1.0) : 1.0;
  vec3 c0 = mix(n0, n1, w0);
  vec3 c1 = mix(n0, n1, w1);
  float a0 = mix(t0, t1, w0);
  float a1 = mix(t0, t1, w1);
  ta += a0;
  tb += a1;
  e0 += a0 * c0;
  e1 += a0 * (c1 - c0) + (a1 - a0) * c0;
  e2 += (a1 - a0) * (c1 - c0);
}

// The next node once the part ending at u1 is done (past every node at u1).
int trcMemberPassNodes(bool used, float sf, float sb, int next, float u1)
{
  float ds = sb - sf;
  while (used && ds > 0.0 && next < in_transferFunctionNodes &&
    (trcNodeScalar(next) - sf) / ds <= u1)
  {
    ++next;
  }
  while (used && ds < 0.0 && next >= 0 && (trcNodeScalar(next) - sf) / ds <= u1)
  {
    --next;
  }
  return next;
}
