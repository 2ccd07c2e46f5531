//============================================================================
// TiledRayCast, compute pipeline: what both traversals
// (vtkTiledRayCastTraversalCS.glsl, vtkTiledRayCastGroupTraversalCS.glsl) do
// per workgroup, one invocation per pixel in 8x4 tiles (the paper's tiles, at
// the size measured fastest on the H200: one warp of neighbouring rays): its
// pixels, taking each pixel's entry list, and counting what the frame did.
//
// The counts are for the mapper's statistics (read by the CPU one frame
// later, or at once with SynchronousStatistics), in the order of RayCount in
// vtkTiledRayCastComputePipeline.cxx. They are summed per workgroup in shared
// memory and added once per workgroup, so that the global atomics see one
// add per tile, not one per ray.
//============================================================================
layout(local_size_x = 8, local_size_y = 4) in;

layout(binding = 1, rgba16) uniform writeonly image2D in_colorImage;
uniform ivec2 in_imageSize;
// 1 inside VTK's depth peeling: the heads stay for the volume's next draw of the frame, which
// traverses the same list (the CPU clears them before the next listing). 0: each head is set
// back to 0 as it is taken, so the next frame starts from empty lists without a clear.
uniform int in_keepEntries;

layout(std430, binding = 2) buffer trcRayCountBuffer
{
  uint trcRays;
  uint trcNearPlaneRays;
  uint trcRaysTerminatedEarly;
  uint trcMaximumLayers;
  uint trcStepsLow;
  uint trcStepsHigh;
  uint trcMaximumSteps;
  uint trcRaysStopped; // rays that reached in_maximumSteps in one layer
  uint trcEmptyGroups; // workgroups (8x4 tiles) with no ray
  uint trcRaysIncomplete; // rays whose lists had lost entries
#ifdef TRC_GROUP_ENTRIES
  uint trcEntriesAsked; // written by the CPU's copy of the entry count
  uint trcMixedRays;    // rays with a piece where two or more volumes overlap
#endif
};

shared uint trcGroupRays;
shared uint trcGroupNearPlaneRays;
shared uint trcGroupTerminatedEarly;
shared uint trcGroupMaximumLayers;
shared uint trcGroupSteps;
shared uint trcGroupMaximumSteps;
shared uint trcGroupStopped;
shared uint trcGroupIncomplete;
#ifdef TRC_GROUP_ENTRIES
shared uint trcGroupMixed;
#endif

// This invocation's pixel: the workgroup's 8x4 pixels as four 4x2 blocks, one per 8 consecutive
// invocations. A GPU runs the whole tile as one warp either way, but a CPU implementation
// (llvmpipe) runs 8 invocations per SIMD vector, and a 4x2 block of rays walks more alike than
// a row of 8.
ivec2 trcTilePixel()
{
  uint lane = gl_LocalInvocationIndex;
  ivec2 inBlock = ivec2(lane & 3u, (lane >> 2u) & 1u);
  ivec2 block = ivec2((lane >> 3u) & 1u, lane >> 4u);
  return ivec2(gl_WorkGroupID.xy) * ivec2(8, 4) + block * ivec2(4, 2) + inBlock;
}

// First in main, reached by every invocation: the workgroup's counts start at zero. Returns this
// invocation's pixel.
ivec2 trcBeginTile()
{
  if (gl_LocalInvocationIndex == 0u)
  {
    trcGroupRays = 0u;
    trcGroupNearPlaneRays = 0u;
    trcGroupTerminatedEarly = 0u;
    trcGroupMaximumLayers = 0u;
    trcGroupSteps = 0u;
    trcGroupMaximumSteps = 0u;
    trcGroupStopped = 0u;
    trcGroupIncomplete = 0u;
#ifdef TRC_GROUP_ENTRIES
    trcGroupMixed = 0u;
#endif
  }
  barrier();
  return trcTilePixel();
}

// One ray's counts (a ray of the tile whose pixel had entries): steps and layers taken, whether
// it started at the near plane, ended opaque, or stopped at in_maximumSteps.
void trcCountRay(int steps, uint layers, bool startedNear, bool opaque, bool stopped)
{
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
}

// Last in main, reached by every invocation: the first invocation adds the tile's counts.
void trcEndTile()
{
  barrier();
  if (gl_LocalInvocationIndex == 0u && trcGroupRays == 0u)
  {
    atomicAdd(trcEmptyGroups, 1u);
  }
  if (gl_LocalInvocationIndex == 0u && trcGroupRays > 0u)
  {
    atomicAdd(trcRays, trcGroupRays);
    atomicAdd(trcNearPlaneRays, trcGroupNearPlaneRays);
    atomicAdd(trcRaysTerminatedEarly, trcGroupTerminatedEarly);
    atomicMax(trcMaximumLayers, trcGroupMaximumLayers);
    atomicMax(trcMaximumSteps, trcGroupMaximumSteps);
    atomicAdd(trcRaysStopped, trcGroupStopped);
    atomicAdd(trcRaysIncomplete, trcGroupIncomplete);
#ifdef TRC_GROUP_ENTRIES
    atomicAdd(trcMixedRays, trcGroupMixed);
#endif
    // A 64-bit sum from two words: GLSL 4.30 has no 64-bit atomics.
    uint before = atomicAdd(trcStepsLow, trcGroupSteps);
    if (before + trcGroupSteps < before)
    {
      atomicAdd(trcStepsHigh, 1u);
    }
  }
}

// The first node (index + 1) of the pixel's entry list, 0 for none; the head is set back to 0 for
// the next frame (unless in_keepEntries). A list that lost entries is counted whether or not any
// of them fit (a ray that lost them all has no list), and here, so that no register holds that
// through the walk.
uint trcTakeEntries(ivec2 pixel, bool inImage)
{
  uint word = inImage ? imageLoad(in_entryHeads, pixel).r : 0u;
  if (word != 0u && in_keepEntries == 0)
  {
    imageStore(in_entryHeads, pixel, uvec4(0u));
  }
  if ((word & TRC_ENTRY_LOST) != 0u)
  {
    atomicAdd(trcGroupIncomplete, 1u);
  }
  return word & TRC_ENTRY_NODE;
}
