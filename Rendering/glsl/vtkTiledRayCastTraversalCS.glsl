//TRC::Version
//============================================================================
// TiledRayCast, compute pipeline: the whole traversal of every ray in one
// dispatch, one invocation per pixel in 8x4 workgroups (the paper's tiles, at
// the size measured fastest on the H200: one warp of neighbouring rays). A ray
// takes its pixel's entries in depth order: the first hit is the nearest (a
// near-plane entry before any face),
// and after the ray leaves the mesh at lambda X the next layer is the nearest
// face at or behind X, never one within in_peelEpsilon of the last entry with
// a key at or below its key: the rules of the fragment pipeline's peeling, so
// both pipelines enter the same layers. The ray state lives in registers from
// the first entry to the last step; the colour is written once.
//
// A pixel whose list lost entries (vtkTiledRayCastEntryList.glsl) walks what
// the list holds and is counted as incomplete.
//============================================================================
//TRC::Common::Dec
//TRC::Layout::Dec
//TRC::Integration::Dec
//TRC::Walk::Dec
//TRC::EntryList::Dec

layout(local_size_x = 8, local_size_y = 4) in;

layout(binding = 1, rgba16) uniform writeonly image2D in_colorImage;
uniform ivec2 in_imageSize;
// The most steps one ray may take in one layer (more than any ray can need).
uniform int in_maximumSteps;
uniform float in_peelEpsilon;

// What the frame did, for the mapper's statistics (read by the CPU one frame later, or at once
// with SynchronousStatistics).
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
};

shared uint trcGroupRays;
shared uint trcGroupNearPlaneRays;
shared uint trcGroupTerminatedEarly;
shared uint trcGroupMaximumLayers;
shared uint trcGroupSteps;
shared uint trcGroupMaximumSteps;
shared uint trcGroupStopped;
shared uint trcGroupIncomplete;

// The entry the ray takes next, or 0: the node (index + 1) first in depth order among those
// allowed after an exit at exitLambda from a layer entered at (lastLambda, lastKey).
uint trcNextEntry(uint head, bool first, float exitLambda, float lastLambda, uint lastKey,
  out float lambda, out uint key, out bool nearPlane)
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
    if (!first)
    {
      // Peeling rules: only faces (the near plane is behind the ray now), at or behind the
      // exit, strictly after the last entry in (lambda, key) order.
      if (isNear || l < exitLambda - in_peelEpsilon ||
        (abs(l - lastLambda) <= in_peelEpsilon && k <= lastKey))
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

void main()
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
  }
  barrier();

  // The workgroup's 8x4 pixels as four 4x2 blocks, one per 8 consecutive invocations: a
  // GPU runs the whole tile as one warp either way, but a CPU implementation (llvmpipe) runs
  // 8 invocations per SIMD vector, and a 4x2 block of rays walks more alike than a row of 8.
  uint lane = gl_LocalInvocationIndex;
  ivec2 inBlock = ivec2(lane & 3u, (lane >> 2u) & 1u);
  ivec2 block = ivec2((lane >> 3u) & 1u, lane >> 4u);
  ivec2 pixel = ivec2(gl_WorkGroupID.xy) * ivec2(8, 4) + block * ivec2(4, 2) + inBlock;
  bool inImage = all(lessThan(pixel, in_imageSize));
  uint word = inImage ? imageLoad(in_entryHeads, pixel).r : 0u;
  uint head = word & TRC_ENTRY_NODE;
  if (word != 0u)
  {
    imageStore(in_entryHeads, pixel, uvec4(0u));
  }
  // Counted whether or not any of its entries fit (a ray that lost them all has no list), and
  // here, so that no register holds it through the walk.
  if ((word & TRC_ENTRY_LOST) != 0u)
  {
    atomicAdd(trcGroupIncomplete, 1u);
  }
  vec4 color = vec4(0.0);
  int steps = 0;
  uint layers = 0u;
  if (head != 0u)
  {
    TrcRay ray = trcPixelRay(vec2(pixel) + 0.5);
    float exitLambda = 0.0;
    float lastLambda = 0.0;
    uint lastKey = 0u;
    int status = TRC_WAITING;
    bool startedNear = false;
    while (status == TRC_WAITING)
    {
      float lambda;
      uint key;
      bool nearPlane;
      if (trcNextEntry(head, layers == 0u, exitLambda, lastLambda, lastKey, lambda, key,
            nearPlane) == 0u)
      {
        break;
      }
      if (layers > 0u)
      {
        lambda = max(lambda, exitLambda);
      }
      startedNear = startedNear || nearPlane;
      ++layers;
      lastLambda = lambda;
      lastKey = nearPlane ? TRC_NEAR_PLANE_KEY : key;
      uint tet = key >> 2u;
      int entry = nearPlane ? TRC_NO_FACE : int(key & 3u);
      int stalls = 0;
      status = trcWalk(ray, in_maximumSteps, tet, lambda, entry, stalls, color, steps);
      exitLambda = lambda;
    }
    atomicAdd(trcGroupRays, 1u);
    atomicAdd(trcGroupSteps, uint(steps));
    atomicMax(trcGroupMaximumSteps, uint(steps));
    atomicMax(trcGroupMaximumLayers, layers);
    if (startedNear)
    {
      atomicAdd(trcGroupNearPlaneRays, 1u);
    }
    if (status == TRC_DONE_OPAQUE)
    {
      atomicAdd(trcGroupTerminatedEarly, 1u);
    }
    if (status == TRC_ACTIVE)
    {
      atomicAdd(trcGroupStopped, 1u);
    }
#ifdef TRC_BLEND_MODE
    // The blend modes accumulate something else than colour (vtkTiledRayCastBlendModes.glsl).
    color = trcFinishRay(color);
#endif
  }
  if (inImage)
  {
    imageStore(in_colorImage, pixel, color);
  }

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
    // A 64-bit sum from two words: GLSL 4.30 has no 64-bit atomics.
    uint before = atomicAdd(trcStepsLow, trcGroupSteps);
    if (before + trcGroupSteps < before)
    {
      atomicAdd(trcStepsHigh, 1u);
    }
  }
}
