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
// The list holds in_entryCapacity nodes, sized by the CPU from the entries of
// earlier frames (it never waits for this frame's). Where a view asks for
// more, the GPU sorts it out in rounds: an entry that finds the list full sets
// its pixel's LOST bit; the traversal leaves such pixels PENDING (and walks
// all the others); the list is emptied and drawn again for the pending pixels
// only (indirect draws and dispatches, no-ops when nothing is pending).
//============================================================================
layout(binding = 0, r32ui) uniform coherent uimage2D in_entryHeads;
layout(std430, binding = 0) buffer trcEntryNodeBuffer
{
  uint trcEntryNodes[];
};
layout(std430, binding = 1) buffer trcEntryCountBuffer
{
  // Entries asked for in this round (only the first in_entryCapacity are stored), then the
  // commands of the next round, which vtkTiledRayCastEntryRoundCS.glsl writes.
  uint trcEntryCount;
  uint trcNextFaceDraw[4];  // glDrawArraysIndirect: count, instances, first, base instance
  uint trcNextSliceDraw[4]; // the same for the near-plane slices
  uint trcNextGroups[3];    // glDispatchComputeIndirect: workgroups x, y, z
};
uniform int in_entryCapacity;
// 1 for the first round (every pixel), above for the rounds of pending pixels.
uniform int in_entryRound;

const uint TRC_NEAR_PLANE_ENTRY = 0x80000000u; // in a node's link
const uint TRC_ENTRY_PENDING = 0x80000000u;    // in a head: the pixel waits for this round
const uint TRC_ENTRY_LOST = 0x40000000u;       // in a head: an entry found the list full
const uint TRC_ENTRY_NODE = 0x3FFFFFFFu;       // in a head or link: the node's index + 1

void trcAppendEntry(ivec2 pixel, float lambda, uint key, bool nearPlane)
{
  uint round = 0u;
  if (in_entryRound > 1)
  {
    if ((imageLoad(in_entryHeads, pixel).r & TRC_ENTRY_PENDING) == 0u)
    {
      return; // this pixel's ray has been walked in an earlier round
    }
    round = TRC_ENTRY_PENDING;
  }
  uint node = atomicAdd(trcEntryCount, 1u);
  if (node >= uint(in_entryCapacity))
  {
    imageAtomicOr(in_entryHeads, pixel, TRC_ENTRY_LOST);
    return;
  }
  uint next = imageAtomicExchange(in_entryHeads, pixel, (node + 1u) | round);
  if ((next & TRC_ENTRY_LOST) != 0u)
  {
    // The exchange wrote over a LOST bit: set it again (every exchange that removes it sets
    // it again afterwards, so the pixel's last word has it).
    imageAtomicOr(in_entryHeads, pixel, TRC_ENTRY_LOST);
  }
  trcEntryNodes[3u * node] = floatBitsToUint(lambda);
  trcEntryNodes[3u * node + 1u] = key;
  trcEntryNodes[3u * node + 2u] = (next & TRC_ENTRY_NODE) | (nearPlane ? TRC_NEAR_PLANE_ENTRY : 0u);
}
