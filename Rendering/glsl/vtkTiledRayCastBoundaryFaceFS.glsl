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
// in_peelEpsilon of the last entry point must also have a larger key
// ((tet << 2) | face) than the face entered there: each new layer is then
// strictly after the previous one in (lambda, key) order.
//============================================================================
//TRC::Common::Dec
//TRC::Layout::Dec
//TRC::Peel::Dec

flat in uint ip_tet;
flat in int ip_face;

layout(location = 0) out vec4 fragOutput0;
layout(location = 1) out vec4 fragOutput1;
layout(location = 2) out vec4 fragOutput2;

void main()
{
  TrcRay ray = trcPixelRay(gl_FragCoord.xy);
  vec3 p[4];
  vec3 n[4];
  vec4 field;
  trcLoadTet(ip_tet, p, n, field);
  vec3 a = p[trcFacePoints[ip_face].x];
  float den = dot(n[ip_face], ray.dir);
  // Where the ray crosses the face's plane. The rasteriser says the pixel is
  // on the face; at grazing angles the division is unreliable, so fall back to
  // the rasterised depth, which is what placed the fragment here.
  float lambda = trcLambdaFromWindowDepth(ray, gl_FragCoord.z);
  if (den < 0.0)
  {
    float exact = dot(a - ray.origin, n[ip_face]) / den;
    if (abs(exact - lambda) < 1e-3 * (1.0 + abs(lambda)))
    {
      lambda = exact;
    }
  }
  lambda = max(lambda, in_lambdaNear);
  if (lambda >= ray.lambdaMax)
  {
    // Behind opaque geometry or the far plane.
    discard;
  }
  uint key = (ip_tet << 2u) | uint(ip_face);
  // A new ray has no colour yet; a re-entering one keeps its own (set by peeling).
  vec4 color = vec4(0.0);
  //TRC::Peel::Impl
  // Our own depth buffer orders layers by mu = lambda - lambdaNear (linear in
  // lambda, unlike window depth).
  gl_FragDepth = clamp(lambda - in_lambdaNear, 0.0, 1.0);
  fragOutput0 = trcPackState(ip_tet, lambda, TRC_ACTIVE, ip_face);
  fragOutput1 = color;
  fragOutput2 = trcPackEntry(lambda, key);
}
