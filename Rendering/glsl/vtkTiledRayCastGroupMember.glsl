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

// The mixture of overlapping volumes (trcGroupMixture): over a piece where the volume's scalar
// goes linearly from sf to sb, u from 0 to 1, `next` is the next node its scalar crosses
// (going up, the first above sf; going down, the last below; constant, the node at or below).
int trcMemberFirstNode(float sf, float sb)
{
  int below = trcFindNode(sf);
  if (sb > sf)
  {
    return below + 1;
  }
  return sb < sf && below >= 0 && trcNodeScalar(below) >= sf ? below - 1 : below;
}

// Where on the piece (u) the scalar crosses node `next`, or 1.
float trcMemberCrossing(bool used, float sf, float sb, int next)
{
  float ds = sb - sf;
  bool crosses = (ds > 0.0 && next < in_transferFunctionNodes) || (ds < 0.0 && next >= 0);
  return used && crosses ? (trcNodeScalar(next) - sf) / ds : 1.0;
}

// The volume's share of the part [u0, u1] of the piece, where its attenuation and colour are
// linear: attenuation ta at u0 to tb at u1, emission (attenuation times colour)
// e0 + e1 v + e2 v^2 for v from 0 to 1 over the part.
void trcMemberMixturePart(bool used, float sf, float sb, int next, float u0, float u1,
  inout float ta, inout float tb, inout vec3 e0, inout vec3 e1, inout vec3 e2)
{
  if (!used)
  {
    return;
  }
  float ds = sb - sf;
  int below = ds > 0.0 ? next - 1 : next;
  vec3 c0;
  vec3 c1;
  float a0;
  float a1;
  trcEvaluate(sf + u0 * ds, below, c0, a0);
  trcEvaluate(sf + u1 * ds, below, c1, a1);
  ta += a0;
  tb += a1;
  e0 += a0 * c0;
  e1 += a0 * (c1 - c0) + (a1 - a0) * c0;
  e2 += (a1 - a0) * (c1 - c0);
}

// The next node once the part ending at u1 is done (past every node at u1).
int trcMemberPassNodes(bool used, float sf, float sb, int next, float u1)
{
  float ds = sb - sf;
  while (used && ds > 0.0 && next < in_transferFunctionNodes &&
    (trcNodeScalar(next) - sf) / ds <= u1)
  {
    ++next;
  }
  while (used && ds < 0.0 && next >= 0 && (trcNodeScalar(next) - sf) / ds <= u1)
  {
    --next;
  }
  return next;
}
