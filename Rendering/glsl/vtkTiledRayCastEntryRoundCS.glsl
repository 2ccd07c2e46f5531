//TRC::Version
//============================================================================
// TiledRayCast, compute pipeline: after the traversal of round in_entryRound,
// one invocation decides on the GPU whether another round is needed (the list
// lost entries: vtkTiledRayCastEntryList.glsl) and writes the next round's
// indirect draws and dispatch: the whole mesh and image if so, nothing if not.
// The CPU never waits for this: it queues every round and those not needed
// draw and dispatch nothing.
//============================================================================
//TRC::EntryList::Dec

layout(local_size_x = 1) in;

// The first of the traversal's counts (vtkTiledRayCastTraversalCS.glsl) that this shader
// writes: trcEntriesAsked, then trcEntryRounds.
layout(std430, binding = 2) buffer trcRayCountBuffer
{
  uint trcCountsBefore[9];
  uint trcEntriesAsked;
  uint trcEntryRounds;
};

uniform int in_faceVertices;
uniform int in_sliceVertices; // 0 when the near plane does not cut the mesh
uniform ivec2 in_groups;

void main()
{
  uint asked = trcEntryCount;
  bool again = asked > uint(in_entryCapacity);
  if (in_entryRound == 1)
  {
    trcEntriesAsked = asked;
  }
  if (again)
  {
    trcEntryRounds = uint(in_entryRound);
    trcEntryCount = 0u;
  }
  trcNextFaceDraw[0] = again ? uint(in_faceVertices) : 0u;
  trcNextFaceDraw[1] = 1u;
  trcNextFaceDraw[2] = 0u;
  trcNextFaceDraw[3] = 0u;
  trcNextSliceDraw[0] = again ? uint(in_sliceVertices) : 0u;
  trcNextSliceDraw[1] = 1u;
  trcNextSliceDraw[2] = 0u;
  trcNextSliceDraw[3] = 0u;
  trcNextGroups[0] = again ? uint(in_groups.x) : 0u;
  trcNextGroups[1] = again ? uint(in_groups.y) : 1u;
  trcNextGroups[2] = 1u;
}
