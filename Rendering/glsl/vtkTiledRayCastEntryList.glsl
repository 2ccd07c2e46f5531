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
//============================================================================
layout(binding = 0, r32ui) uniform coherent uimage2D in_entryHeads;
layout(std430, binding = 0) buffer trcEntryNodeBuffer
{
  uint trcEntryNodes[];
};
layout(std430, binding = 1) buffer trcEntryCountBuffer
{
  // Entries asked for in this frame; only the first in_entryCapacity are stored, and the
  // CPU, which reads this count, grows the list and draws the entries again if it is larger.
  uint trcEntryCount;
};
uniform int in_entryCapacity;

const uint TRC_NEAR_PLANE_ENTRY = 0x80000000u;

void trcAppendEntry(ivec2 pixel, float lambda, uint key, bool nearPlane)
{
  uint node = atomicAdd(trcEntryCount, 1u);
  if (node >= uint(in_entryCapacity))
  {
    return;
  }
  uint next = imageAtomicExchange(in_entryHeads, pixel, node + 1u);
  trcEntryNodes[3u * node] = floatBitsToUint(lambda);
  trcEntryNodes[3u * node + 1u] = key;
  trcEntryNodes[3u * node + 2u] = next | (nearPlane ? TRC_NEAR_PLANE_ENTRY : 0u);
}
