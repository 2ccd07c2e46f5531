//TRC::Version
//============================================================================
// TiledRayCast, compute pipeline: one traversal of several overlapping
// volumes (vtkTiledRayCastGroupTraversal composes it). Each volume has its own
// mesh, transfer function, matrix and rays: its code is the one-volume code
// with a suffix per volume (vtkTiledRayCastGroupMember.glsl), called here by
// the lines marked EachMember, one per volume. Every volume's entries are in
// one per-pixel list (TRC_GROUP_ENTRIES: a fourth word says whose).
//
// Volumes meet on a ray through mu = lambda - lambdaNear, the same for every
// volume at the same point (the volume matrices are affine, and lambda runs
// from the near plane to the far plane). Each volume is inside a tet or
// waiting for its next entry. Where one volume is inside and every other is
// ahead or done, that volume walks alone with its own walk (trcWalk, the
// one-volume traversal's loop and arithmetic) up to the nearest entry of
// another, so that a ray sees what it sees when that volume is drawn alone.
// Where two or more are inside, the ray goes from event to event (a volume's
// span ends: it crosses a node of its transfer function or leaves its tet; or
// a volume enters), integrating each piece as their mixture
// (trcCompositeMixture, docs/design.md "Overlapping media"). Within a span a
// volume's attenuation and colour are linear (vtkTiledRayCastGroupMember.glsl):
// an event reads only the moving volume's mesh and transfer function, and a
// piece sums every inside volume's linear terms from registers, so the work
// per event does not grow with the other volumes' reads. Each volume takes its
// entries with the one-volume traversal's rules (trcNextEntry,
// vtkTiledRayCastEntryList.glsl).
//
// Each volume's state is a global of its own (trcVolume0, ...), never indexed
// by a volume index that varies per ray: NVIDIA's compiler keeps such arrays
// in local memory, not in registers.
//============================================================================
// The pixel of this invocation's ray, which every volume's code reads (trcMemberRay): a global
// named without the trc prefix, so that renaming each volume's code leaves it one for all.
vec2 groupRayPixel;
//TRC::Group::Members
// The list's reading side too (trcNextEntry, in_peelEpsilon: each volume's entries only).
#define TRC_ENTRY_TRAVERSAL
//TRC::EntryList::Dec

// The 8x4 tiles: layout, pixels, list heads and counts (vtkTiledRayCastTraversalTile.glsl).
//TRC::TraversalTile::Dec

// The most steps one ray may take in one layer of one volume.
uniform int in_maximumSteps;
// Early ray termination (the first volume's).
uniform float in_groupEarlyTermination;

#ifdef TRC_PEEL_STAGE
// Taking part in VTK's dual depth peeling: the ranges it asks for
// (vtkTiledRayCastVolumetricPeelRanges.glsl); the front one goes to in_colorImage, the back one here.
//TRC::VolumetricPeel::Dec
layout(binding = 3, rgba16) uniform writeonly image2D in_backColorImage;
#endif

const float TRC_GROUP_FAR = 3.4e38;
// Parts of a mixture are cut into panels of at most this optical depth, each integrated with
// 3-point Gauss-Legendre (error bound in docs/design.md).
const float TRC_GROUP_PANEL_DEPTH = 0.5;
const int TRC_GROUP_MAXIMUM_PANELS = 4096;

//------------------------------------------------------------------------------
// A part of length len where the summed attenuation goes linearly from ta to tb and the summed
// emission (sum of tau_i c_i) is e0 + e1 u + e2 u^2, u from 0 to 1: in panels of optical depth
// up to TRC_GROUP_PANEL_DEPTH, each integrated with 3-point Gauss-Legendre (exact for the
// emission, which is quadratic; the transmittance within a panel is an exponential of a
// quadratic of at most that depth); a constant medium in closed form.
void trcCompositeMixture(float ta, float tb, vec3 e0, vec3 e1, vec3 e2, float len,
  inout vec4 color)
{
  float depth = 0.5 * (ta + tb) * len;
  if (!(len > 0.0) || !(depth > 0.0))
  {
    return;
  }
  if (ta == tb && all(equal(e1, vec3(0.0))) && all(equal(e2, vec3(0.0))))
  {
    // A constant medium (cell scalars, or flat transfer functions): exact in closed form, one
    // exponential however thick.
    float opacity = 1.0 - exp(-depth);
    color.rgb += (1.0 - color.a) * (e0 / ta) * opacity;
    color.a += (1.0 - color.a) * opacity;
    return;
  }
  int n = clamp(int(ceil(depth / TRC_GROUP_PANEL_DEPTH)), 1, TRC_GROUP_MAXIMUM_PANELS);
  float h = len / float(n);
  // The 3 points and weights, written out: no array indexed in the loop.
  const float x0 = 0.1127016653792583;
  const float x2 = 0.8872983346207417;
  const float wEnds = 5.0 / 18.0;
  const float wMiddle = 8.0 / 18.0;
  for (int j = 0; j < n; ++j)
  {
    float a0 = mix(ta, tb, float(j) / float(n));
    float a1 = mix(ta, tb, float(j + 1) / float(n));
    float da = 0.5 * (a1 - a0);
    float u0 = (float(j) + x0) / float(n);
    float u1 = (float(j) + 0.5) / float(n);
    float u2 = (float(j) + x2) / float(n);
    vec3 c = wEnds * (e0 + u0 * (e1 + u0 * e2)) * exp(-h * x0 * (a0 + da * x0)) +
      wMiddle * (e0 + u1 * (e1 + u1 * e2)) * exp(-h * 0.5 * (a0 + da * 0.5)) +
      wEnds * (e0 + u2 * (e1 + u2 * e2)) * exp(-h * x2 * (a0 + da * x2));
    color.rgb += (1.0 - color.a) * h * c;
    color.a += (1.0 - color.a) * (1.0 - exp(-0.5 * h * (a0 + a1)));
    if (color.a >= in_groupEarlyTermination)
    {
      return;
    }
  }
}

#ifdef TRC_GROUP_SHARED_CODE
// One copy of the member code for every volume (vtkTiledRayCastSharedMemberCode): the names the
// lines written per volume use stand for it, with trcMemberIndex set to the volume.
//TRC::EachMember #define TrcMember_v@ TrcMember
//TRC::EachMember #define trcMemberPart_v@ trcMemberPart
//TRC::EachMember void trcMemberStart_v@(vec2 fragCoord, out TrcMember s) { trcMemberIndex = @; trcMemberStart(fragCoord, s); }
#define TrcRay_v0 TrcRay
//TRC::EachMember #define in_lambdaNear_v@ in_lambdaNear[@]
TrcRay trcPixelRay_v0(vec2 fragCoord)
{
  trcMemberIndex = 0;
  return trcPixelRay(fragCoord);
}
float trcLambdaFromWindowDepth_v0(TrcRay ray, float depth)
{
  trcMemberIndex = 0;
  return trcLambdaFromWindowDepth(ray, depth);
}
float trcMemberWorldScale_v0()
{
  trcMemberIndex = 0;
  return trcMemberWorldScale();
}
#endif

//------------------------------------------------------------------------------
// Each volume's state along this invocation's ray (vtkTiledRayCastGroupMember.glsl's TrcMember).
//TRC::EachMember TrcMember_v@ trcVolume@;

#ifdef TRC_GROUP_SHARED_CODE
// Volume m's event, and volume `alone`'s walk: its state gathered from its global (a select per
// volume, the state staying in registers), moved on by the one copy of the member code, which
// reads the volume's own mesh and transfer function, and put back. A warp whose rays move
// different volumes runs one body, not one per volume.
bool trcGroupMemberEvent(int m, inout int steps, inout uint layers, inout bool startedNear,
  inout bool stopped)
{
  TrcMember s = trcVolume0;
//TRC::EachMember s = m == @ ? trcVolume@ : s;
  trcMemberIndex = m;
  bool moved = trcMemberEvent(s, in_maximumSteps, steps, layers, startedNear, stopped);
//TRC::EachMember trcVolume@ = m == @ ? s : trcVolume@;
  return moved;
}

bool trcGroupMemberWalk(int alone, float bound, inout float mu, inout vec4 color,
  inout int steps, inout bool stopped, out bool inside)
{
  TrcMember s = trcVolume0;
//TRC::EachMember s = alone == @ ? trcVolume@ : s;
  trcMemberIndex = alone;
  trcMemberAdvance(s, mu + in_lambdaNear[alone]);
  bool goesOn = trcMemberWalk(s, bound, in_maximumSteps, color, steps, stopped);
  inside = s.inside;
  mu = max(mu, s.from - in_lambdaNear[alone]);
//TRC::EachMember trcVolume@ = alone == @ ? s : trcVolume@;
  return goesOn;
}
#else
// Volume m's event, and volume `alone`'s walk, in the volume's own renamed code: a warp whose
// rays move different volumes runs the body of each.
bool trcGroupMemberEvent(int m, inout int steps, inout uint layers, inout bool startedNear,
  inout bool stopped)
{
  bool moved = true;
//TRC::EachMember if (m == @) moved = trcMemberEvent_v@(trcVolume@, in_maximumSteps, steps, layers, startedNear, stopped);
  return moved;
}

bool trcGroupMemberWalk(int alone, float bound, inout float mu, inout vec4 color,
  inout int steps, inout bool stopped, out bool inside)
{
  bool goesOn = true;
  inside = true;
//TRC::EachMember if (alone == @) { trcMemberAdvance_v@(trcVolume@, mu + in_lambdaNear_v@); goesOn = trcMemberWalk_v@(trcVolume@, bound, in_maximumSteps, color, steps, stopped); inside = trcVolume@.inside; mu = max(mu, trcVolume@.from - in_lambdaNear_v@); }
  return goesOn;
}
#endif

// Volume k (inside, pending or done) in the search for the nearest event: the end of its span
// (a node of its transfer function, or its tet's exit), or its entry, in mu; the lowest index first on a tie (the others follow at the same place).
void trcGroupConsider(int k, bool inside, bool pending, float exitMu, float entryMu,
  inout int m, inout float event, inout int count, inout int alone)
{
  float at = inside ? exitMu : entryMu;
  count += inside ? 1 : 0;
  alone = inside ? k : alone;
  if ((inside || pending) && (m < 0 || at < event))
  {
    m = k;
    event = at;
  }
}

// Volume k left its layer at its `from`: its next entry, with the one-volume traversal's peeling
// rules (among its own entries), never before where it left.
void trcGroupNextEntry(uint head, int k)
{
  float from = 0.0;
  float lastLambda = 0.0;
  uint lastKey = 0u;
//TRC::EachMember if (k == @) { from = trcVolume@.from; lastLambda = trcVolume@.lastLambda; lastKey = trcVolume@.lastKey; }
  float lambda;
  uint key;
  bool nearPlane;
  bool pending =
    trcNextEntry(head, uint(k), false, from, lastLambda, lastKey, lambda, key, nearPlane) != 0u;
  lambda = max(lambda, from);
//TRC::EachMember if (k == @) { trcVolume@.pending = pending; trcVolume@.entryLambda = lambda; trcVolume@.entryKey = key; trcVolume@.entryNear = nearPlane; }
}

// Volume `alone` inside, every other ahead of it or done: its own walk up to the nearest entry
// of another (mu, where it stopped). False where the ray ends. Else it stopped at that entry,
// inside (handedBack: the event loop takes at least that entry before the next walk), or left
// its layer (it takes its next entry).
bool trcGroupWalkAlone(uint head, int alone, inout float mu, inout vec4 color, inout int steps,
  inout bool stopped, out bool handedBack)
{
  float bound = TRC_GROUP_FAR;
//TRC::EachMember if (@ != alone && trcVolume@.pending) bound = min(bound, trcVolume@.entryLambda - in_lambdaNear_v@);
  bool inside;
  // It walks from where the ray is (its span may have begun before the last event).
  bool goesOn = trcGroupMemberWalk(alone, bound, mu, color, steps, stopped, inside);
  if (goesOn && !inside)
  {
    trcGroupNextEntry(head, alone);
  }
  handedBack = inside;
  return goesOn;
}

// The walk of every volume along this invocation's ray from mu = muFrom to muTo (the whole ray
// outside VTK's depth peeling), integrated into `color`: each volume starts before its first
// entry, crosses what lies before muFrom without integrating it, and stops at muTo.
void trcGroupTraverse(uint head, vec2 fragCoord, float muFrom, float muTo, inout vec4 color,
  inout int steps, inout uint layers, inout bool startedNear, inout bool opaque,
  inout bool stopped, inout bool mixed)
{
  // Where opaque geometry, the far plane or the range ends the ray, in mu.
  float muMax = muTo;
  groupRayPixel = fragCoord;
//TRC::EachMember trcMemberStart_v@(fragCoord, trcVolume@);
  // A unit of mu is the same length for every volume: one register for all.
  float worldScale = trcMemberWorldScale_v0();
#ifdef TRC_PEEL_STAGE
//TRC::EachMember trcVolume@.lambdaMin = muFrom + in_lambdaNear_v@;
//TRC::EachMember trcVolume@.lambdaMax = min(trcVolume@.lambdaMax, muTo + in_lambdaNear_v@);
#endif
//TRC::EachMember muMax = min(muMax, trcVolume@.lambdaMax - in_lambdaNear_v@);
//TRC::EachMember trcVolume@.pending = trcNextEntry(head, @u, true, 0.0, 0.0, 0u, trcVolume@.entryLambda, trcVolume@.entryKey, trcVolume@.entryNear) != 0u;
  float mu = -TRC_GROUP_FAR;
  int count = 0;  // volumes inside
  int alone = -1; // the last of them
  // After a walk that stopped at another volume's entry, at least one event before the next.
  bool handedBack = false;
  bool finished = false;
  // The walks of lone volumes and the event loop are apart, each a tight loop of its own (a
  // CPU implementation runs every branch of a loop body: walks inside the event loop made
  // every event cost every volume's walk).
  while (!finished)
  {
    if (count == 1 && !trcGroupWalkAlone(head, alone, mu, color, steps, stopped, handedBack))
    {
      opaque = color.a >= in_groupEarlyTermination;
      break;
    }
    while (true)
    {
      // The nearest event: volume m's span ends, or it enters. Only m moves on.
      int m = -1;
      float event = TRC_GROUP_FAR;
      count = 0;
//TRC::EachMember trcGroupConsider(@, trcVolume@.inside, trcVolume@.pending, trcVolume@.spanEnd - in_lambdaNear_v@, trcVolume@.entryLambda - in_lambdaNear_v@, m, event, count, alone);
      if (m < 0)
      {
        finished = true;
        break;
      }
      if (count == 1 && !handedBack)
      {
        break; // one volume inside: its own walk
      }
      handedBack = false;
      // Integrate up to the event (or the end of the ray) the mixture of the volumes inside:
      // each one's attenuation and colour are linear until its span ends, which no event
      // before this one did (docs/design.md, "Overlapping media").
      float end = min(event, muMax);
#ifdef TRC_PEEL_STAGE
      // Before the range the volumes only move on.
      float start = max(mu, muFrom);
#else
      float start = mu;
#endif
      if (count > 0 && end > start)
      {
        float ta = 0.0;
        float tb = 0.0;
        vec3 e0 = vec3(0.0);
        vec3 e1 = vec3(0.0);
        vec3 e2 = vec3(0.0);
//TRC::EachMember if (trcVolume@.inside) trcMemberPart_v@(trcVolume@, start + in_lambdaNear_v@, end + in_lambdaNear_v@, ta, tb, e0, e1, e2);
        // One volume inside here only after a walk that stopped at the bound (a sliver).
        trcCompositeMixture(ta, tb, e0, e1, e2, (end - start) * worldScale, color);
        mixed = mixed || count > 1;
      }
      if (color.a >= in_groupEarlyTermination)
      {
        opaque = true;
        finished = true;
        break;
      }
      if (event >= muMax)
      {
        finished = true;
        break;
      }
      mu = max(mu, event);
      // Volume m moves on: into its next span, the next tet, or the tet it enters; or it takes
      // its next entry (the one-volume traversal's peeling rules).
      bool moved = trcGroupMemberEvent(m, steps, layers, startedNear, stopped);
      if (!moved)
      {
        trcGroupNextEntry(head, m);
      }
    }
  }
}

#ifdef TRC_PEEL_STAGE
// Window depths `range` as mu (volume 0's ray: mu is the same for every volume at a point); an
// empty range where it is.
vec2 trcGroupRange(vec2 fragCoord, vec2 range)
{
  if (!(range.x < range.y))
  {
    return vec2(TRC_GROUP_FAR, -TRC_GROUP_FAR);
  }
  TrcRay_v0 ray = trcPixelRay_v0(fragCoord);
  return vec2(trcLambdaFromWindowDepth_v0(ray, range.x), trcLambdaFromWindowDepth_v0(ray, range.y)) -
    in_lambdaNear_v0;
}
#endif

void main()
{
  ivec2 pixel = trcBeginTile();
  bool inImage = all(lessThan(pixel, in_imageSize));
  uint head = trcTakeEntries(pixel, inImage);
  vec4 color = vec4(0.0);
#ifdef TRC_PEEL_STAGE
  vec4 backColor = vec4(0.0);
  head = inImage && trcPeelPixelDone(pixel) ? 0u : head;
#endif
  if (head != 0u)
  {
    vec2 fragCoord = vec2(pixel) + 0.5;
    int steps = 0;
    uint layers = 0u;
    bool startedNear = false;
    bool opaque = false;
    bool stopped = false;
    bool mixed = false;
#ifdef TRC_PEEL_STAGE
    // The front range, then the back one behind it, each a walk of its own from the ray's first
    // entries (the back one crosses what lies before it without integrating it); the back one
    // only while the front leaves the ray below the early termination.
    vec4 ranges = trcPeelRanges(pixel);
    vec2 front = trcGroupRange(fragCoord, ranges.xy);
    vec2 back = trcGroupRange(fragCoord, ranges.zw);
    if (front.x < front.y)
    {
      trcGroupTraverse(head, fragCoord, front.x, front.y, color, steps, layers, startedNear,
        opaque, stopped, mixed);
    }
    if (!opaque && back.x < back.y)
    {
      trcGroupTraverse(head, fragCoord, back.x, back.y, backColor, steps, layers, startedNear,
        opaque, stopped, mixed);
    }
#else
    trcGroupTraverse(head, fragCoord, -TRC_GROUP_FAR, TRC_GROUP_FAR, color, steps, layers,
      startedNear, opaque, stopped, mixed);
#endif
    trcCountRay(steps, layers, startedNear, opaque, stopped);
    if (mixed)
    {
      atomicAdd(trcGroupMixed, 1u);
    }
  }
  if (inImage)
  {
    imageStore(in_colorImage, pixel, color);
#ifdef TRC_PEEL_STAGE
    imageStore(in_backColorImage, pixel, backColor);
#endif
  }
  trcEndTile();
}
