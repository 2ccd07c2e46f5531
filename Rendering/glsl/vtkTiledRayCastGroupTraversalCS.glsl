//TRC::Version
//============================================================================
// TiledRayCast, compute pipeline: one traversal of up to four overlapping
// volumes (vtkTiledRayCastGroupPrograms composes it). Each volume has its own
// mesh, transfer function, matrix and rays: its code is the one-volume code
// with a suffix per volume (vtkTiledRayCastGroupMember.glsl), reached here
// through the trcGroup* functions below. Every volume's entries are in one
// per-pixel list (TRC_GROUP_ENTRIES: a fourth word says whose).
//
// Volumes meet on a ray through mu = lambda - lambdaNear, the same for every
// volume at the same point (the volume matrices are affine, and lambda runs
// from the near plane to the far plane). Each volume is inside a tet or
// waiting for its next entry; the ray goes from event to event (a volume
// leaves its tet, or a volume enters), integrating each piece with the
// volumes inside: one alone as its own walk does (trcIntegrate, exact), two
// or more as their mixture (trcGroupMixture, docs/design.md "Overlapping
// media"). Each volume takes its entries with the one-volume traversal's
// rules (trcNextEntry, vtkTiledRayCastEntryList.glsl), so where it overlaps
// no other, a ray sees what it sees alone.
//============================================================================
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

const int TRC_GROUP_MAXIMUM_STALLS = 64; // as TRC_MAXIMUM_STALLS of the walk
const uint TRC_GROUP_NEAR_PLANE_KEY = 0xFFFFFFFEu;
const float TRC_GROUP_FAR = 3.4e38;
// Parts of a mixture are cut into panels of at most this optical depth, each integrated with
// 3-point Gauss-Legendre (error bound in docs/design.md).
const float TRC_GROUP_PANEL_DEPTH = 0.5;
const int TRC_GROUP_MAXIMUM_PANELS = 4096;

//------------------------------------------------------------------------------
// One function per thing the traversal needs of volume m: each line marked EachMember is
// repeated for every volume, @ replaced by its index.
float trcGroupExit(int m, vec3 origin, vec3 dir, uint tet, int entry, float lambda,
  out int exitFace, out vec4 field, out uvec4 words)
{
  exitFace = 0;
  field = vec4(0.0);
  words = uvec4(0u);
  float exitLambda = lambda;
//TRC::EachMember if (m == @) exitLambda = trcMemberExit_v@(origin, dir, tet, entry, lambda, exitFace, field, words);
  return exitLambda;
}

bool trcGroupNext(int m, uvec4 words, int exitFace, inout uint tet, inout int entry)
{
  bool inside = false;
//TRC::EachMember if (m == @) inside = trcMemberNext_v@(words, exitFace, tet, entry);
  return inside;
}

void trcGroupIntegrate(int m, float sf, float sb, float d, inout vec4 color)
{
//TRC::EachMember if (m == @) trcIntegrate_v@(sf, sb, d, color);
}

//------------------------------------------------------------------------------
// A part of length len where the summed attenuation goes linearly from ta to tb and the summed
// emission (sum of tau_i c_i) is e0 + e1 u + e2 u^2, u from 0 to 1: in panels of optical depth
// up to TRC_GROUP_PANEL_DEPTH, each integrated with 3-point Gauss-Legendre (exact for the
// emission, which is quadratic; the transmittance within a panel is an exponential of a
// quadratic of at most that depth).
void trcCompositeMixture(float ta, float tb, vec3 e0, vec3 e1, vec3 e2, float len,
  inout vec4 color)
{
  float depth = 0.5 * (ta + tb) * len;
  if (!(len > 0.0) || !(depth > 0.0))
  {
    return;
  }
  int n = clamp(int(ceil(depth / TRC_GROUP_PANEL_DEPTH)), 1, TRC_GROUP_MAXIMUM_PANELS);
  float h = len / float(n);
  const vec3 x = vec3(0.1127016653792583, 0.5, 0.8872983346207417);
  const vec3 w = vec3(5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0);
  for (int j = 0; j < n; ++j)
  {
    float a0 = mix(ta, tb, float(j) / float(n));
    float a1 = mix(ta, tb, float(j + 1) / float(n));
    vec3 c = vec3(0.0);
    for (int k = 0; k < 3; ++k)
    {
      float u = (float(j) + x[k]) / float(n);
      vec3 e = e0 + u * (e1 + u * e2);
      c += w[k] * e * exp(-h * x[k] * (a0 + 0.5 * (a1 - a0) * x[k]));
    }
    color.rgb += (1.0 - color.a) * h * c;
    color.a += (1.0 - color.a) * (1.0 - exp(-0.5 * h * (a0 + a1)));
    if (color.a >= in_groupEarlyTermination)
    {
      return;
    }
  }
}

// Where two or more volumes overlap, over a piece of world length d, volume m's scalar going
// linearly from sf[m] to sb[m] (m inside): the mixture, attenuation sum tau_i, emission
// sum tau_i c_i (docs/design.md, "Overlapping media"). The piece is cut at every node of every
// volume's transfer function that its scalar crosses; between cuts each volume's attenuation
// and colour are linear, the sums are linear and quadratic (trcCompositeMixture). Each
// volume's code appears once (a line per volume), never behind a loop over volumes.
void trcGroupMixture(bool inside[TRC_GROUP_MEMBERS], float sf[TRC_GROUP_MEMBERS],
  float sb[TRC_GROUP_MEMBERS], float d, inout vec4 color)
{
  bool used[TRC_GROUP_MEMBERS];
  int next[TRC_GROUP_MEMBERS];
  int crossings = 0;
  for (int m = 0; m < TRC_GROUP_MEMBERS; ++m)
  {
    // A tet touching a non-finite scalar is transparent, as in trcIntegrate.
    used[m] = inside[m] && !isnan(sf[m]) && !isnan(sb[m]) && !isinf(sf[m]) && !isinf(sb[m]);
  }
//TRC::EachMember next[@] = used[@] ? trcMemberFirstNode_v@(sf[@], sb[@]) : -1;
//TRC::EachMember crossings += used[@] ? trcMemberNodes_v@() : 0;
  float u0 = 0.0;
  for (int part = 0; part <= crossings && u0 < 1.0; ++part)
  {
    float u1 = 1.0;
//TRC::EachMember u1 = min(u1, trcMemberCrossing_v@(used[@], sf[@], sb[@], next[@]));
    u1 = max(u1, u0);
    float ta = 0.0;
    float tb = 0.0;
    vec3 e0 = vec3(0.0);
    vec3 e1 = vec3(0.0);
    vec3 e2 = vec3(0.0);
//TRC::EachMember trcMemberMixturePart_v@(used[@], sf[@], sb[@], next[@], u0, u1, ta, tb, e0, e1, e2);
    trcCompositeMixture(ta, tb, e0, e1, e2, d * (u1 - u0), color);
    if (color.a >= in_groupEarlyTermination)
    {
      return;
    }
//TRC::EachMember next[@] = trcMemberPassNodes_v@(used[@], sf[@], sb[@], next[@], u1);
    u0 = u1;
  }
}

void main()
{
  trcClearGroupCounts();
  barrier();

  ivec2 pixel = trcTilePixel();
  bool inImage = all(lessThan(pixel, in_imageSize));
  uint head = trcTakeEntries(pixel, inImage);
  vec4 color = vec4(0.0);
  if (head != 0u)
  {
    vec2 fragCoord = vec2(pixel) + 0.5;
    // Each volume's ray, and its state: inside tet[m] from lambda from[m] to exitAt[m] (its
    // own lambda), or waiting for the entry at entryLambda[m] (pending[m]).
    vec3 origin[TRC_GROUP_MEMBERS];
    vec3 dir[TRC_GROUP_MEMBERS];
    float lambdaNear[TRC_GROUP_MEMBERS];
    float worldScale[TRC_GROUP_MEMBERS];
    bool inside[TRC_GROUP_MEMBERS];
    uint tet[TRC_GROUP_MEMBERS];
    int entry[TRC_GROUP_MEMBERS];
    float from[TRC_GROUP_MEMBERS];
    float exitAt[TRC_GROUP_MEMBERS];
    int exitFace[TRC_GROUP_MEMBERS];
    vec4 field[TRC_GROUP_MEMBERS];
    uvec4 words[TRC_GROUP_MEMBERS];
    int layerSteps[TRC_GROUP_MEMBERS];
    int stalls[TRC_GROUP_MEMBERS];
    bool pending[TRC_GROUP_MEMBERS];
    float entryLambda[TRC_GROUP_MEMBERS];
    uint entryKey[TRC_GROUP_MEMBERS];
    bool entryNear[TRC_GROUP_MEMBERS];
    float lastLambda[TRC_GROUP_MEMBERS];
    uint lastKey[TRC_GROUP_MEMBERS];
    float sf[TRC_GROUP_MEMBERS];
    float sb[TRC_GROUP_MEMBERS];
    // Where opaque geometry or the far plane ends the ray, in mu.
    float muMax = TRC_GROUP_FAR;
    float lambdaMax[TRC_GROUP_MEMBERS];
//TRC::EachMember trcMemberRay_v@(fragCoord, origin[@], dir[@], lambdaNear[@], lambdaMax[@], worldScale[@]);
    for (int m = 0; m < TRC_GROUP_MEMBERS; ++m)
    {
      muMax = min(muMax, lambdaMax[m] - lambdaNear[m]);
      // Every state word defined before it is read (a volume that never enters keeps these).
      inside[m] = false;
      tet[m] = 0u;
      entry[m] = -1;
      from[m] = 0.0;
      exitAt[m] = 0.0;
      exitFace[m] = 0;
      field[m] = vec4(0.0);
      words[m] = uvec4(0u);
      layerSteps[m] = 0;
      stalls[m] = 0;
      sf[m] = 0.0;
      sb[m] = 0.0;
      lastLambda[m] = 0.0;
      lastKey[m] = 0u;
      pending[m] = trcNextEntry(head, uint(m), true, 0.0, 0.0, 0u, entryLambda[m], entryKey[m],
                     entryNear[m]) != 0u;
    }
    int steps = 0;
    uint layers = 0u;
    bool startedNear = false;
    bool opaque = false;
    bool stopped = false;
    bool mixed = false;
    float mu = -TRC_GROUP_FAR;
    while (true)
    {
      // The nearest event: volume m leaves its tet or enters (the lowest index first on a tie,
      // the others follow at the same place). Only m moves on, so that each volume's walk
      // appears once in the loop (a CPU implementation runs every branch of it).
      int m = -1;
      float event = TRC_GROUP_FAR;
      int count = 0;
      int alone = 0;
      for (int k = 0; k < TRC_GROUP_MEMBERS; ++k)
      {
        float at = TRC_GROUP_FAR;
        if (inside[k])
        {
          at = exitAt[k] - lambdaNear[k];
          ++count;
          alone = k;
        }
        else if (pending[k])
        {
          at = entryLambda[k] - lambdaNear[k];
        }
        if ((inside[k] || pending[k]) && (m < 0 || at < event))
        {
          m = k;
          event = at;
        }
      }
      if (m < 0)
      {
        break;
      }
      // Integrate up to the event (or the end of the ray) with the volumes inside, each from
      // where it is to there in its own lambda (its own exit exactly, when the event is that).
      float end = min(event, muMax);
      if (count > 0 && end > mu)
      {
        float to[TRC_GROUP_MEMBERS];
        for (int k = 0; k < TRC_GROUP_MEMBERS; ++k)
        {
          to[k] = from[k];
          if (inside[k])
          {
            to[k] = k == m && end == event ? exitAt[k] : min(exitAt[k], end + lambdaNear[k]);
            to[k] = max(to[k], from[k]);
            sf[k] = dot(field[k].xyz, origin[k] + from[k] * dir[k]) + field[k].w;
            sb[k] = dot(field[k].xyz, origin[k] + to[k] * dir[k]) + field[k].w;
          }
        }
        if (count == 1)
        {
          // One volume: its own integration, exactly as its own walk does.
          trcGroupIntegrate(
            alone, sf[alone], sb[alone], (to[alone] - from[alone]) * worldScale[alone], color);
        }
        else
        {
          trcGroupMixture(inside, sf, sb, (end - mu) * worldScale[alone], color);
          mixed = true;
        }
        for (int k = 0; k < TRC_GROUP_MEMBERS; ++k)
        {
          from[k] = to[k];
        }
      }
      if (color.a >= in_groupEarlyTermination)
      {
        opaque = true;
        break;
      }
      if (event >= muMax)
      {
        break;
      }
      mu = max(mu, event);
      // Volume m moves on: to the next tet, to its next entry (the one-volume traversal's
      // peeling rules), or into the tet it enters.
      bool walks = true;
      if (inside[m])
      {
        from[m] = exitAt[m];
        if (stalls[m] <= TRC_GROUP_MAXIMUM_STALLS && layerSteps[m] < in_maximumSteps &&
          trcGroupNext(m, words[m], exitFace[m], tet[m], entry[m]))
        {
          ++layerSteps[m];
        }
        else
        {
          stopped = stopped || layerSteps[m] >= in_maximumSteps;
          inside[m] = false;
          walks = false;
          pending[m] = trcNextEntry(head, uint(m), false, from[m], lastLambda[m], lastKey[m],
                         entryLambda[m], entryKey[m], entryNear[m]) != 0u;
          entryLambda[m] = max(entryLambda[m], from[m]);
        }
      }
      else
      {
        pending[m] = false;
        inside[m] = true;
        ++layers;
        startedNear = startedNear || entryNear[m];
        lastLambda[m] = entryLambda[m];
        lastKey[m] = entryNear[m] ? TRC_GROUP_NEAR_PLANE_KEY : entryKey[m];
        tet[m] = entryKey[m] >> 2u;
        entry[m] = entryNear[m] ? -1 : int(entryKey[m] & 3u);
        from[m] = entryLambda[m];
        layerSteps[m] = 1;
        stalls[m] = 0;
      }
      if (walks)
      {
        ++steps;
        exitAt[m] = trcGroupExit(
          m, origin[m], dir[m], tet[m], entry[m], from[m], exitFace[m], field[m], words[m]);
        stalls[m] = exitAt[m] > from[m] ? 0 : stalls[m] + 1;
      }
    }
    atomicAdd(trcGroupRays, 1u);
    atomicAdd(trcGroupSteps, uint(steps));
    atomicMax(trcGroupMaximumSteps, uint(steps));
    atomicMax(trcGroupMaximumLayers, layers);
    if (startedNear)
    {
      atomicAdd(trcGroupNearPlaneRays, 1u);
    }
    if (opaque)
    {
      atomicAdd(trcGroupTerminatedEarly, 1u);
    }
    if (stopped)
    {
      atomicAdd(trcGroupStopped, 1u);
    }
    if (mixed)
    {
      atomicAdd(trcGroupMixed, 1u);
    }
  }
  if (inImage)
  {
    imageStore(in_colorImage, pixel, color);
  }

  barrier();
  trcAddGroupCounts();
}
