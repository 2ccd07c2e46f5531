//============================================================================
// TiledRayCast: the walk of one ray through the mesh, shared by the fragment
// pipeline's ray-casting passes and the compute pipeline's traversal, so that
// both integrate every segment with the same arithmetic.
//
// From tet `tet` at `lambda`, entered through face `entry`, the ray goes to the
// neighbour across the face it leaves through, integrating each segment, until
// it leaves the mesh (TRC_WAITING: it may re-enter at a deeper boundary layer),
// reaches opaque geometry or the far plane (TRC_DONE_DEPTH), becomes opaque
// (TRC_DONE_OPAQUE), or has taken maximumSteps steps (TRC_ACTIVE: tet, lambda
// and entry then say where to go on).
//============================================================================

// Steps in a row that leave a ray where it is: beyond this, the ray is caught between
// degenerate tets and leaves the mesh where it stands (it may re-enter at the next layer).
const int TRC_MAXIMUM_STALLS = 64;

// The face of `tet` shared with `previous` (layouts that store no entry face).
int trcSharedFace(uint previous, uvec4 neighborWords)
{
  int entry = TRC_NO_FACE;
  for (int f = 0; f < 4; ++f)
  {
    entry = trcNeighborTet(neighborWords, f) == previous ? f : entry;
  }
  return entry;
}

// Below this |det| / scale^1.5 (det = 6 V, scale the sum of the squared edges from point 0; a
// regular tet has 0.19) a tet is flat as far as float arithmetic can tell: its face planes
// nearly coincide, their steps from the ray's point are all rounding noise, and a face of three
// collinear points has a normal of pure noise. Its exit is then the face the ray passes through.
const float TRC_FLAT_TET = 1.0e-5;

// Whether the ray through `here` along `dir` passes through face f of t (an edge or corner
// counts), by the signs of the three edges' moments about the ray (Pluecker): all alike inside.
// Independent of the face's normal, so a face of collinear points (all three moments of one
// line, one against the other two) is never passed through.
// The corners are picked as trcFacePoints lists them, without indexing p by a table (see
// trcExitStep).
bool trcRayCrossesFace(TrcTet t, int f, vec3 here, vec3 dir)
{
  vec3 a = (f == 0 ? t.p[1] : t.p[0]) - here;
  vec3 b = (f == 0 ? t.p[2] : (f == 1 ? t.p[3] : (f == 2 ? t.p[1] : t.p[2]))) - here;
  vec3 c = (f == 0 ? t.p[3] : (f == 1 ? t.p[2] : (f == 2 ? t.p[3] : t.p[1]))) - here;
  float u = dot(dir, cross(a, b));
  float v = dot(dir, cross(b, c));
  float w = dot(dir, cross(c, a));
  return (u >= 0.0 && v >= 0.0 && w >= 0.0) || (u <= 0.0 && v <= 0.0 && w <= 0.0);
}

// How far (in lambda) the ray goes in tet t from lambda, entered through face `entry`, and the
// face it leaves through: the nearest plane it leaves through, never the entry face. Shared by
// the walk and the traversal of overlapping volumes (vtkTiledRayCastGroupMember.glsl).
// Distances are measured from the ray's current point, next to the tet, not from its origin on
// the near plane: in a flat tet, planes a few float steps apart at lambda ~ 0.5 are then told
// apart (the wrong one skips a tet). In a tet flatter than that (TRC_FLAT_TET) the nearest
// plane means nothing: the face the ray passes through is taken, the nearest plane only where
// rounding lets the ray pass through none.
float trcExitStep(TrcTet t, TrcRay ray, float lambda, int entry, out int exitFace)
{
  vec3 here = ray.origin + lambda * ray.dir;
  vec3 e1 = t.p[1] - t.p[0];
  vec3 e2 = t.p[2] - t.p[0];
  vec3 e3 = t.p[3] - t.p[0];
  float scale = dot(e1, e1) + dot(e2, e2) + dot(e3, e3);
  bool flatTet = abs(dot(e1, cross(e2, e3))) <= TRC_FLAT_TET * scale * sqrt(scale);
  float exitStep = 3.4e38;
  exitFace = -1;
  float nearestStep = 3.4e38;
  int nearestFace = -1;
  float steepest = -3.4e38;
  int steepestFace = 0;
  for (int f = 0; f < 4; ++f)
  {
    if (f == entry)
    {
      continue;
    }
    vec3 normal = trcFaceNormal(t, f);
    float den = dot(normal, ray.dir);
    if (den > steepest)
    {
      steepest = den;
      steepestFace = f;
    }
    if (den > 0.0)
    {
      // A point of face f: point 1 for face 0, point 0 for the others (trcFacePoints).
      // Chosen without indexing p by a table: NVIDIA's compiler then keeps p in local
      // memory, not in registers.
      float step = dot((f == 0 ? t.p[1] : t.p[0]) - here, normal) / den;
      if (step < nearestStep)
      {
        nearestStep = step;
        nearestFace = f;
      }
      if (step < exitStep && (!flatTet || trcRayCrossesFace(t, f, here, ray.dir)))
      {
        exitStep = step;
        exitFace = f;
      }
    }
  }
  if (exitFace < 0)
  {
    exitFace = nearestFace;
    exitStep = nearestStep;
  }
  if (exitFace < 0)
  {
    // No face faces away from the ray (a degenerate tet, or a ray inside a
    // face's plane): leave through the most favourable face without moving.
    exitFace = steepestFace;
    exitStep = 0.0;
  }
  return exitStep;
}

int trcWalk(TrcRay ray, int maximumSteps, inout uint tet, inout float lambda, inout int entry,
  inout int stalls, inout vec4 color, inout int steps)
{
  uint previous = TRC_NO_NEIGHBOR;
  int status = TRC_ACTIVE;
  int taken = 0;
#ifdef TRC_SHADING
  vec3 toViewer = trcToViewer(ray);
#endif
  while (status == TRC_ACTIVE && taken < maximumSteps)
  {
    ++taken;
    TrcTet t;
    trcLoadTet(tet, t);
    uvec4 neighborWords = trcLoadNeighborWords(tet);
    if (!TRC_LAYOUT_STORES_ENTRY_FACES && entry == TRC_FACE_FROM_PREVIOUS)
    {
      entry = trcSharedFace(previous, neighborWords);
    }

    int exitFace;
    float exitStep = trcExitStep(t, ray, lambda, entry, exitFace);
    float exitLambda = lambda + max(exitStep, 0.0);
    stalls = exitLambda > lambda ? 0 : stalls + 1;

    bool stopped = exitLambda >= ray.lambdaMax;
    float endLambda = min(exitLambda, ray.lambdaMax);
    // Integrated from where the clipping planes let the ray begin: before that the walk only
    // crosses tets (a segment wholly before it has no length and adds nothing).
    float fromLambda = max(lambda, ray.lambdaMin);
    float sFront = dot(t.field.xyz, ray.origin + fromLambda * ray.dir) + t.field.w;
    float sBack = dot(t.field.xyz, ray.origin + endLambda * ray.dir) + t.field.w;
    float segmentLength = (endLambda - fromLambda) * ray.worldScale;
#ifdef TRC_GRADIENT_OPACITY
    // The tet's gradient opacity scales its attenuation: the same as scaling the length
    // (vtkTiledRayCastGradientOpacity.glsl).
    segmentLength *= trcGradientOpacity(t.field.xyz);
#endif
#ifdef TRC_SHADING
    // Integrated unshaded on its own, then shaded as a whole (vtkTiledRayCastShading.glsl).
    vec4 segment = vec4(0.0);
    trcIntegrate(sFront, sBack, segmentLength, segment);
    trcCompositeShaded(segment, t.field.xyz, toViewer, color);
#else
    trcIntegrate(sFront, sBack, segmentLength, color);
#endif
    lambda = endLambda;

    if (color.a >= in_earlyTerminationOpacity)
    {
      status = TRC_DONE_OPAQUE;
    }
    else if (stopped)
    {
      status = TRC_DONE_DEPTH;
    }
    else
    {
      uint next = trcNeighborTet(neighborWords, exitFace);
#ifdef TRC_SKIP_EMPTY_SPACE
      // An invisible tet ends the visible part: the ray jumps to the next of its faces behind.
      bool leaves = next == TRC_NO_NEIGHBOR || !trcTetVisible(next);
#else
      bool leaves = next == TRC_NO_NEIGHBOR;
#endif
      if (leaves || stalls > TRC_MAXIMUM_STALLS)
      {
        status = TRC_WAITING;
      }
      else
      {
        previous = TRC_LAYOUT_STORES_ENTRY_FACES ? previous : tet;
        tet = next;
        entry = trcNeighborFace(neighborWords, exitFace);
      }
    }
  }
  if (!TRC_LAYOUT_STORES_ENTRY_FACES && status == TRC_ACTIVE && entry == TRC_FACE_FROM_PREVIOUS)
  {
    // The walk ends inside the mesh: resolve the entry face now, the next walk
    // does not know where the ray came from.
    entry = trcSharedFace(previous, trcLoadNeighborWords(tet));
  }
  steps += taken;
  return status;
}
