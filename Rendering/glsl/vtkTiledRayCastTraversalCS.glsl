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

#ifdef TRC_PEEL_STAGE
// Taking part in VTK's dual depth peeling: the ranges it asks for
// (vtkTiledRayCastVolumetricPeelRanges.glsl); the front one goes to in_colorImage, the back one here.
//TRC::VolumetricPeel::Dec
layout(binding = 3, rgba16) uniform writeonly image2D in_backColorImage;
#endif

// Where a ray's walk through the layers of its entry list (from node `head`) stands: inside tet
// `tet` at `lambda`, entered through face `entry` (`inside`: stopped at the end of a range it
// resumes from), or waiting for the next entry after the last one taken (`lastLambda`,
// `lastKey`; the ray left the mesh at `exitLambda`).
struct TrcLayerWalk
{
  uint head;
  float exitLambda;
  float lastLambda;
  uint lastKey;
  uint entered;
  bool inside;
  uint tet;
  float lambda;
  int entry;
  int stalls;
};

TrcLayerWalk trcStartLayerWalk(uint head)
{
  return TrcLayerWalk(head, 0.0, 0.0, 0u, 0u, false, 0u, 0.0, TRC_NO_FACE, 0);
}

// The walk on through every layer, integrating what lies between ray.lambdaMin and
// ray.lambdaMax into `color`; the status it ends with. Stopped at ray.lambdaMax inside a tet,
// or before an entry beyond it, the walk resumes from there with the next range of the ray.
int trcTraverse(inout TrcLayerWalk w, TrcRay ray, inout vec4 color, inout int steps,
  inout bool startedNear)
{
  int status = TRC_WAITING;
  if (w.inside)
  {
    status = trcWalk(ray, in_maximumSteps, w.tet, w.lambda, w.entry, w.stalls, color, steps);
    w.exitLambda = w.lambda;
  }
  while (status == TRC_WAITING)
  {
    float lambda;
    uint key;
    bool nearPlane;
    if (trcNextEntry(w.head, w.entered == 0u, w.exitLambda, w.lastLambda, w.lastKey, lambda,
          key, nearPlane) == 0u)
    {
      break;
    }
    if (w.entered > 0u)
    {
      lambda = max(lambda, w.exitLambda);
    }
#ifdef TRC_PEEL_STAGE
    if (lambda >= ray.lambdaMax)
    {
      // Entries come in depth order: this one and the next are beyond the range's end, and
      // this one is taken again by the next range. (Without peeling the entry pass lists none
      // beyond the ray's end.)
      w.inside = false;
      return TRC_DONE_DEPTH;
    }
#endif
    startedNear = startedNear || nearPlane;
    ++w.entered;
    w.lastLambda = lambda;
    w.lastKey = nearPlane ? TRC_NEAR_PLANE_KEY : key;
    w.tet = key >> 2u;
    w.entry = nearPlane ? TRC_NO_FACE : int(key & 3u);
    w.stalls = 0;
    status = trcWalk(ray, in_maximumSteps, w.tet, lambda, w.entry, w.stalls, color, steps);
    w.lambda = lambda;
    w.exitLambda = lambda;
  }
  w.inside = status == TRC_DONE_DEPTH;
  return status;
}

#ifdef TRC_PEEL_STAGE
// The ray cut to window depths range.x to range.y (within its clipping planes): empty when the
// range is.
bool trcCutRay(inout TrcRay ray, vec2 range, float fromLambda, float toLambda)
{
  ray.lambdaMin = max(fromLambda, trcLambdaFromWindowDepth(ray, range.x));
  ray.lambdaMax = min(toLambda, trcLambdaFromWindowDepth(ray, range.y));
  return range.x < range.y && ray.lambdaMin < ray.lambdaMax;
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
  int steps = 0;
  uint layers = 0u;
  if (head != 0u)
  {
    TrcRay ray = trcPixelRay(vec2(pixel) + 0.5);
    bool startedNear = false;
    TrcLayerWalk walk = trcStartLayerWalk(head);
#ifdef TRC_PEEL_STAGE
    // The front range, then the back one behind it: the walk goes on from where the front
    // range ended (the back one starts at or behind its end).
    vec4 ranges = trcPeelRanges(pixel);
    const float fromLambda = ray.lambdaMin;
    const float toLambda = ray.lambdaMax;
    int status = TRC_DONE_DEPTH;
    if (trcCutRay(ray, ranges.xy, fromLambda, toLambda))
    {
      status = trcTraverse(walk, ray, color, steps, startedNear);
    }
    if (status == TRC_DONE_DEPTH && trcCutRay(ray, ranges.zw, fromLambda, toLambda))
    {
      status = trcTraverse(walk, ray, backColor, steps, startedNear);
    }
#else
    int status = trcTraverse(walk, ray, color, steps, startedNear);
#endif
    layers = walk.entered;
    trcCountRay(steps, layers, startedNear, status == TRC_DONE_OPAQUE, status == TRC_ACTIVE);
#ifdef TRC_BLEND_MODE
    // The blend modes accumulate something else than colour (vtkTiledRayCastBlendModes.glsl).
    color = trcFinishRay(color);
#endif
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
