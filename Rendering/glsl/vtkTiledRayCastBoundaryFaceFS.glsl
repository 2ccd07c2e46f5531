//TRC::Version
//============================================================================
// TiledRayCast: first hit and depth peeling. Each fragment of a front-facing
// boundary face starts (or restarts) its pixel's ray in the face's tet.
//
// First hit: the nearest face wins the depth test.
// Peeling: only pixels whose ray left the mesh (TRC_WAITING) at lambda X take
// part, and only faces at or behind X: the nearest of those is where the ray
// re-enters. Faces are ordered by their exact lambda (written as depth), so a
// crack's coincident faces re-enter the ray where it left. To never loop on
// faces that share an edge or a plane at a grazing angle, a face within
// in_peelEpsilon of the last entry point must come after the face entered
// there in (lambda, key) order ((tet << 2) | face): each new layer is then
// strictly after the previous one. (Not by key alone: a face a hair behind a
// flat sheet entered before it must still be entered.)
//
// Compute pipeline (TRC_ENTRY_LIST): one pass, no depth test, every fragment
// appended to its pixel's list of entries; the traversal applies the same
// order and the same rules when it takes the next layer.
//============================================================================
//TRC::Common::Dec
//TRC::Layout::Dec
//TRC::Peel::Dec

flat in uint ip_tet;
flat in int ip_face;
flat in vec2 ip_corner0;
flat in vec2 ip_corner1;
flat in vec2 ip_corner2;
flat in int ip_testCoverage;
// Pixels: how far outside an edge a pixel centre may lie and still be covered (more than
// the rounding of the corners' positions, so that faces sharing an edge leave no gap).
uniform float in_coverageTolerance;

// Whether the pixel centre lies in the face, tested against the unsnapped corners (the
// vertex shader grew the face so that every such pixel gets a fragment).
bool trcCovers(vec2 q)
{
  vec2 e0 = ip_corner1 - ip_corner0;
  vec2 e1 = ip_corner2 - ip_corner1;
  vec2 e2 = ip_corner0 - ip_corner2;
  float side = e0.x * e1.y - e0.y * e1.x > 0.0 ? 1.0 : -1.0;
  vec3 distance = side *
    vec3(e0.x * (q.y - ip_corner0.y) - e0.y * (q.x - ip_corner0.x),
      e1.x * (q.y - ip_corner1.y) - e1.y * (q.x - ip_corner1.x),
      e2.x * (q.y - ip_corner2.y) - e2.y * (q.x - ip_corner2.x));
  vec3 lengths = vec3(length(e0), length(e1), length(e2));
  return all(greaterThanEqual(distance, -in_coverageTolerance * lengths));
}

//TRC::EntryTarget::Dec

void main()
{
  TrcRay ray = trcPixelRay(gl_FragCoord.xy);
  vec3 a;
  vec3 normal;
  trcLoadFace(ip_tet, ip_face, a, normal);
  float den = dot(normal, ray.dir);
  // Where the ray crosses the face's plane. At grazing angles the division is
  // unreliable: there the rasterised depth, which placed the fragment here, is
  // used unless the two agree. (Not at other angles: the depth of a grown face
  // is interpolated between moved corners and is off where the face was grown.)
  float lambda = trcLambdaFromWindowDepth(ray, gl_FragCoord.z);
  if (den < 0.0)
  {
    float exact = dot(a - ray.origin, normal) / den;
    bool grazing = -den < 1e-4 * length(normal) * length(ray.dir);
    if (!grazing || abs(exact - lambda) < 1e-3 * (1.0 + abs(lambda)))
    {
      lambda = exact;
    }
  }
  // How much lambda changes from one pixel to the next: taken before any fragment of the quad
  // is discarded (derivatives need them all).
  float lambdaPerPixel = fwidth(lambda);
  //TRC::Peel::Early
  if (ip_testCoverage != 0 && !trcCovers(gl_FragCoord.xy))
  {
    discard;
  }
  // The pass draws with depth clamping: nothing is clipped at the near plane, and this test
  // takes its place. Crossed behind the near plane, the face leaves the ray to the near-plane
  // slices (it starts inside the mesh there), except within half a pixel of the line where
  // the face meets the plane: faces and slices overlap there, where the clipper and the
  // slices' own corners would round differently and leave a seam of lost rays. (An entry kept
  // in that band starts the ray at the near plane in this tet; a slice's entry, if the pixel
  // has one too, comes first.)
  if (lambda < in_lambdaNear - 0.5 * lambdaPerPixel)
  {
    discard;
  }
  lambda = max(lambda, in_lambdaNear);
  if (lambda >= ray.lambdaMax || ray.lambdaMin >= ray.lambdaMax)
  {
    // Behind opaque geometry, the far plane or a clipping plane (or the clipping planes leave
    // nothing of this ray).
    discard;
  }
  uint key = (ip_tet << 2u) | uint(ip_face);
#ifdef TRC_ENTRY_LIST
  // Compute pipeline: every crossing is listed; the traversal takes them in depth order.
  trcAppendEntry(ivec2(gl_FragCoord.xy), lambda, key, false);
#else
  // A new ray has no colour yet; a re-entering one keeps its own (set by peeling).
  vec4 color = vec4(0.0);
  //TRC::Peel::Impl
  // Our own depth buffer orders layers by mu = lambda - lambdaNear (linear in
  // lambda, unlike window depth).
  gl_FragDepth = clamp(lambda - in_lambdaNear, 0.0, 1.0);
  fragOutput0 = trcPackState(ip_tet, lambda, TRC_ACTIVE, ip_face);
  fragOutput1 = color;
  fragOutput2 = trcPackEntry(lambda, key);
#endif
}
