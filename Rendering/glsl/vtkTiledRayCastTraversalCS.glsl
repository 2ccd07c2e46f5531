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
// The list's reading side too (trcNextEntry, in_peelEpsilon).
#define TRC_ENTRY_TRAVERSAL
//TRC::EntryList::Dec

// The 8x4 tiles: layout, pixels, list heads and counts (vtkTiledRayCastTraversalTile.glsl).
//TRC::TraversalTile::Dec

// The most steps one ray may take in one layer (more than any ray can need).
uniform int in_maximumSteps;

void main()
{
  trcClearGroupCounts();
  barrier();

  ivec2 pixel = trcTilePixel();
  bool inImage = all(lessThan(pixel, in_imageSize));
  uint head = trcTakeEntries(pixel, inImage);
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
  trcAddGroupCounts();
}
