//============================================================================
// TiledRayCast, compute pipeline: per-pixel lists of the places where a ray
// enters the mesh (every front-facing boundary face that covers the pixel, and
// the near plane where the camera is inside the mesh), written by one raster
// pass and read by the traversal, which takes them in depth order. This
// replaces the fragment pipeline's first hit and its depth-peeling passes.
//
// A node is three words: lambda (float bits), key ((tet << 2) | face), and the
// index + 1 of the next node of the same pixel, its top bit set for a
// near-plane entry. A pixel's head holds the index + 1 of its latest node, 0
// for none; the traversal sets it back to 0 after reading it, so the next
// frame starts from empty lists without a clear.
//
// Overlapping volumes traversed together (TRC_GROUP_ENTRIES, vtkTiledRayCastGroupTraversalCS.glsl)
// list every volume's entries in one list: a node then has a fourth word, the volume's index in
// the group (in_groupMember, set per volume's raster pass), and lambda is that volume's own.
//
// The list holds in_entryCapacity nodes, sized by the CPU from the entries of
// earlier frames (it never waits for this frame's). An entry that finds the
// list full sets its pixel's LOST bit: the traversal walks what the list holds
// and counts the ray as incomplete, and the mapper draws the frame again
// (verified frames) or warns.
//============================================================================
layout(binding = 0, r32ui) uniform coherent uimage2D in_entryHeads;
layout(std430, binding = 0) buffer trcEntryNodeBuffer
{
  uint trcEntryNodes[];
};
layout(std430, binding = 1) buffer trcEntryCountBuffer
{
  // Entries asked for in this frame: all that the view has; only the first
  // in_entryCapacity are stored.
  uint trcEntryCount;
};
uniform int in_entryCapacity;
#ifdef TRC_GROUP_ENTRIES
const uint TRC_ENTRY_WORDS = 4u;
uniform int in_groupMember;
#else
const uint TRC_ENTRY_WORDS = 3u;
#endif

const uint TRC_NEAR_PLANE_ENTRY = 0x80000000u; // in a node's link
const uint TRC_ENTRY_LOST = 0x80000000u;       // in a head: an entry found the list full
const uint TRC_ENTRY_NODE = 0x7FFFFFFFu;       // in a head or link: the node's index + 1

void trcAppendEntry(ivec2 pixel, float lambda, uint key, bool nearPlane)
{
  uint node = atomicAdd(trcEntryCount, 1u);
  if (node >= uint(in_entryCapacity))
  {
    imageAtomicOr(in_entryHeads, pixel, TRC_ENTRY_LOST);
    return;
  }
  uint next = imageAtomicExchange(in_entryHeads, pixel, node + 1u);
  if ((next & TRC_ENTRY_LOST) != 0u)
  {
    // The exchange wrote over a LOST bit: set it again (every exchange that removes it sets
    // it again afterwards, so the pixel's last word has it).
    imageAtomicOr(in_entryHeads, pixel, TRC_ENTRY_LOST);
  }
  uint i = TRC_ENTRY_WORDS * node;
  trcEntryNodes[i] = floatBitsToUint(lambda);
  trcEntryNodes[i + 1u] = key;
  trcEntryNodes[i + 2u] = (next & TRC_ENTRY_NODE) | (nearPlane ? TRC_NEAR_PLANE_ENTRY : 0u);
#ifdef TRC_GROUP_ENTRIES
  trcEntryNodes[i + 3u] = uint(in_groupMember);
#endif
}

#ifdef TRC_ENTRY_TRAVERSAL
// The reading side, for the traversals (vtkTiledRayCastTraversalCS.glsl and, per volume,
// vtkTiledRayCastGroupTraversalCS.glsl): one copy of the peeling rules, so that a volume of a
// group enters the layers it enters alone. The raster passes only append.
uniform float in_peelEpsilon;

// The entry the ray takes next, or 0: the node (index + 1) first in depth order among those
// allowed after an exit at exitLambda from a layer entered at (lastLambda, lastKey). In a group,
// among volume `member`'s entries only; the one-volume body stays as it is (the hot path: no
// extra word read, no extra variable in the loop).
#ifdef TRC_GROUP_ENTRIES
uint trcNextEntry(uint head, uint member, bool first, float exitLambda, float lastLambda,
  uint lastKey, out float lambda, out uint key, out bool nearPlane)
#else
uint trcNextEntry(uint head, bool first, float exitLambda, float lastLambda, uint lastKey,
  out float lambda, out uint key, out bool nearPlane)
#endif
{
  uint best = 0u;
  lambda = 0.0;
  key = 0u;
  nearPlane = false;
  for (uint node = head; node != 0u;)
  {
    uint i = TRC_ENTRY_WORDS * (node - 1u);
    float l = uintBitsToFloat(trcEntryNodes[i]);
    uint k = trcEntryNodes[i + 1u];
    uint link = trcEntryNodes[i + 2u];
    bool isNear = link >= TRC_NEAR_PLANE_ENTRY;
    uint current = node;
    node = link & ~TRC_NEAR_PLANE_ENTRY;
#ifdef TRC_GROUP_ENTRIES
    if (trcEntryNodes[i + 3u] != member)
    {
      continue;
    }
#endif
    if (!first)
    {
      // Peeling rules: only faces (the near plane is behind the ray now), at or behind the
      // exit, strictly after the last entry in (lambda, key) order. Faces within in_peelEpsilon
      // of it count as behind it only by that order, whatever their key: a face a hair in
      // front of a zero-thickness layer's (a flat sheet over a tet's face) is still entered.
      if (isNear || l < exitLambda - in_peelEpsilon ||
        (abs(l - lastLambda) <= in_peelEpsilon &&
          (l < lastLambda || (l == lastLambda && k <= lastKey))))
      {
        continue;
      }
    }
    // Depth order: a near-plane entry first, then lambda, then the key.
    bool better = best == 0u || (isNear && !nearPlane) ||
      (isNear == nearPlane && (l < lambda || (l == lambda && k < key)));
    if (better)
    {
      best = current;
      lambda = l;
      key = k;
      nearPlane = isNear;
    }
  }
  return best;
}
#endif
