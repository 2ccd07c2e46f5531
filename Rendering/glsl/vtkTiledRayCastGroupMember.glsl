//============================================================================
// TiledRayCast: what the traversal of overlapping volumes
// (vtkTiledRayCastGroupTraversalCS.glsl) needs of one volume, written with
// the names of the one-volume shaders. vtkTiledRayCastGroupPrograms appends
// this to a volume's own common, layout, integration and walk code and gives
// every trc*, Trc*, TRC_* and in_* name of the whole a suffix per volume
// (_v0, _v1, ...): each volume keeps its own mesh, transfer function, rays and
// uniforms, and the traversal calls trcMemberExit_v1 and so on.
//============================================================================

// The volume's ray through a pixel: its origin and direction in the volume's (shifted) object
// coordinates, the lambda of the near plane (lambda - lambdaNear is the same for every volume
// at the same point), where opaque geometry or the far plane ends it, and the world length of
// a unit of lambda.
void trcMemberRay(vec2 fragCoord, out vec3 origin, out vec3 dir, out float lambdaNear,
  out float lambdaMax, out float worldScale)
{
  TrcRay ray = trcPixelRay(fragCoord);
  origin = ray.origin;
  dir = ray.dir;
  lambdaNear = in_lambdaNear;
  lambdaMax = ray.lambdaMax;
  worldScale = ray.worldScale;
}

// Tet `tet`, entered through face `entry` (or TRC_NO_FACE) at lambda: where the ray leaves it
// and through which face, its scalar field and its neighbour words (the walk's arithmetic).
float trcMemberExit(vec3 origin, vec3 dir, uint tet, int entry, float lambda, out int exitFace,
  out vec4 field, out uvec4 words)
{
  TrcTet t;
  trcLoadTet(tet, t);
  words = trcLoadNeighborWords(tet);
  TrcRay ray;
  ray.origin = origin;
  ray.dir = dir;
  float exitStep = trcExitStep(t, ray, lambda, entry, exitFace);
  field = t.field;
  return lambda + max(exitStep, 0.0);
}

// The tet behind face exitFace, or false where the ray leaves the volume (or its visible part).
bool trcMemberNext(uvec4 words, int exitFace, inout uint tet, inout int entry)
{
  uint next = trcNeighborTet(words, exitFace);
#ifdef TRC_SKIP_EMPTY_SPACE
  bool leaves = next == TRC_NO_NEIGHBOR || !trcTetVisible(next);
#else
  bool leaves = next == TRC_NO_NEIGHBOR;
#endif
  if (leaves)
  {
    return false;
  }
  tet = next;
  entry = trcNeighborFace(words, exitFace);
  return true;
}

int trcMemberNodes()
{
  return in_transferFunctionNodes;
}
