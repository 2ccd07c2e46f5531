//============================================================================
// TiledRayCast: declarations shared by every fragment shader of the mapper.
//
// Coordinates: "object" means the mesh's coordinates minus the layout's shift
// (docs/design.md), the space the mesh textures are stored in. A pixel's ray is
//   x(lambda) = trcRayOrigin + lambda * trcRayDir
// where the origin and direction are affine functions of the pixel's NDC
// position, computed on the CPU in double precision: lambda = mu - mu_c, where
// mu runs from 0 on the near plane to 1 on the far plane and mu_c is the centre
// plane of the mesh, so that lambda stays small where the mesh is.
//============================================================================

// Pixel (fragment) to NDC inside the viewport being rendered.
uniform vec2 in_viewportSize;

// Affine ray set-up: value = v0 + ndc.x * vx + ndc.y * vy.
uniform vec3 in_rayOrigin0;
uniform vec3 in_rayOriginX;
uniform vec3 in_rayOriginY;
uniform vec3 in_rayDir0;
uniform vec3 in_rayDirX;
uniform vec3 in_rayDirY;
// Clip-space w of the ray's near-plane and far-plane points (affine in NDC as
// well), used to turn window depth into mu and back.
uniform vec3 in_wNear;
uniform vec3 in_wFar;
// lambda of the near plane (-mu_c).
uniform float in_lambdaNear;
// Object-to-world linear part, to measure segment lengths in world units.
uniform mat3 in_objectToWorld;
// Early ray termination: a ray stops once its opacity reaches this.
uniform float in_earlyTerminationOpacity;
// The mapper's clipping planes in object coordinates: dot(xyz, x) + w >= 0 is kept.
uniform int in_numberOfClippingPlanes;
uniform vec4 in_clippingPlanes[6];
// Opaque geometry's window depth (the scene before the volume), one texel per
// viewport pixel.
uniform sampler2D in_opaqueDepth;

// The ray state of a pixel is two textures:
//   state (RGBA32F): tet (low 20 bits), lambda, tet (high bits),
//                    status + 8 (entry face + 2)
//   entry (RGBA32F): lambda and key (tet << 2 | face, low 20 bits, high bits) of
//                    the last boundary face the ray entered through (for robust
//                    peeling)
// Ids are stored as exact float values in two parts, never as float bit
// patterns: small ids would be denormal floats, which GPUs may flush to zero.
// Ray status:
const int TRC_MISS = 0;          // the ray never entered the mesh
const int TRC_ACTIVE = 1;        // inside tet state.x, at lambda state.y
const int TRC_WAITING = 2;       // left the mesh at lambda state.y; may re-enter
const int TRC_DONE_DEPTH = 3;    // reached opaque geometry or the far plane
const int TRC_DONE_OPAQUE = 4;   // early ray termination

// Entry face values besides 0..3.
const int TRC_NO_FACE = -1;      // started at the near plane: no entry face
const int TRC_FACE_FROM_PREVIOUS = -2; // entry face is the one shared with the previous tet

const uint TRC_NO_NEIGHBOR = 0xFFFFFFFFu;
// Key of the "boundary face" of a ray that started at the near plane.
const uint TRC_NEAR_PLANE_KEY = 0xFFFFFFFEu;

vec2 trcPackId(uint id)
{
  return vec2(float(id & 0xFFFFFu), float(id >> 20u));
}

uint trcUnpackId(float low, float high)
{
  return (uint(high) << 20u) + uint(low);
}

// state.w = status + 8 * (entry face + 2) + 64 * stalled steps (see trcStalls).
vec4 trcPackState(uint tet, float lambda, int status, int entryFace, int stalls)
{
  vec2 id = trcPackId(tet);
  return vec4(id.x, lambda, id.y, float(status + 8 * (entryFace + 2) + 64 * stalls));
}

vec4 trcPackState(uint tet, float lambda, int status, int entryFace)
{
  return trcPackState(tet, lambda, status, entryFace, 0);
}

uint trcStateTet(vec4 state)
{
  return trcUnpackId(state.x, state.z);
}

vec4 trcPackEntry(float lambda, uint key)
{
  vec2 id = trcPackId(key);
  return vec4(lambda, id.x, id.y, 0.0);
}

uint trcEntryKey(vec4 entry)
{
  return trcUnpackId(entry.y, entry.z);
}

int trcStatus(vec4 state)
{
  return int(state.w) & 7;
}

int trcEntryFace(vec4 state)
{
  return ((int(state.w) >> 3) & 7) - 2;
}

// Steps in a row that did not move the ray forward (degenerate tets): bounded, so that a ray
// caught between degenerate tets cannot loop for ever.
int trcStalls(vec4 state)
{
  return int(state.w) >> 6;
}

struct TrcRay
{
  vec3 origin;
  vec3 dir;
  float wNear;
  float wFar;
  float lambdaMin;  // where the clipping planes let the ray begin (-3.4e38 without them)
  float lambdaMax;  // where opaque geometry, the far plane or a clipping plane stops the ray
  float worldScale; // world length of a unit of lambda
};

vec2 trcPixelNDC(vec2 fragCoord)
{
  return 2.0 * fragCoord / in_viewportSize - 1.0;
}

// mu in [0,1] (near plane to far plane) of NDC depth z on this ray.
float trcMuFromNDCDepth(TrcRay ray, float z)
{
  float a = ray.wNear * (1.0 + z);
  return a / (a + ray.wFar * (1.0 - z));
}

// NDC depth of mu on this ray.
float trcNDCDepthFromMu(TrcRay ray, float mu)
{
  float n = (1.0 - mu) * ray.wNear;
  float f = mu * ray.wFar;
  return (f - n) / (f + n);
}

float trcWindowDepthFromLambda(TrcRay ray, float lambda)
{
  float mu = clamp(lambda - in_lambdaNear, 0.0, 1.0);
  return 0.5 * trcNDCDepthFromMu(ray, mu) + 0.5;
}

float trcLambdaFromWindowDepth(TrcRay ray, float depth)
{
  return trcMuFromNDCDepth(ray, 2.0 * depth - 1.0) + in_lambdaNear;
}

// The pixel's ray, unbounded: what the uniforms give it (the traversal of overlapping volumes
// makes it again where it needs it rather than hold it for every volume).
TrcRay trcPixelRayGeometry(vec2 fragCoord)
{
  vec2 ndc = trcPixelNDC(fragCoord);
  TrcRay ray;
  ray.origin = in_rayOrigin0 + ndc.x * in_rayOriginX + ndc.y * in_rayOriginY;
  ray.dir = in_rayDir0 + ndc.x * in_rayDirX + ndc.y * in_rayDirY;
  ray.wNear = in_wNear.x + ndc.x * in_wNear.y + ndc.y * in_wNear.z;
  ray.wFar = in_wFar.x + ndc.x * in_wFar.y + ndc.y * in_wFar.z;
  ray.lambdaMin = -3.4e38;
  ray.lambdaMax = 3.4e38;
  ray.worldScale = length(in_objectToWorld * ray.dir);
  return ray;
}

TrcRay trcPixelRay(vec2 fragCoord)
{
  TrcRay ray = trcPixelRayGeometry(fragCoord);
  float opaque = texelFetch(in_opaqueDepth, ivec2(fragCoord), 0).r;
  // Depth 1 is the far plane: the ray ends there when nothing opaque is in the way.
  ray.lambdaMax = trcLambdaFromWindowDepth(ray, opaque);
  // The kept half-spaces of the clipping planes cut the ray to one interval: a plane the ray
  // runs into the kept side of raises its start, one it runs out of lowers its end.
  for (int i = 0; i < in_numberOfClippingPlanes; ++i)
  {
    vec4 plane = in_clippingPlanes[i];
    float at0 = dot(plane.xyz, ray.origin) + plane.w;
    float rate = dot(plane.xyz, ray.dir);
    if (rate > 0.0)
    {
      ray.lambdaMin = max(ray.lambdaMin, -at0 / rate);
    }
    else if (rate < 0.0)
    {
      ray.lambdaMax = min(ray.lambdaMax, -at0 / rate);
    }
    else if (at0 < 0.0)
    {
      ray.lambdaMax = -3.4e38; // parallel to the plane, on its removed side
    }
  }
  return ray;
}

// Points of face f (opposite point f), counter-clockwise seen from outside.
const ivec3 trcFacePoints[4] = ivec3[4](ivec3(1, 2, 3), ivec3(0, 3, 2), ivec3(0, 1, 3),
  ivec3(0, 2, 1));

#ifdef TRC_SKIP_EMPTY_SPACE
// Empty-space skipping: one bit per tet, 1 where the transfer function leaves it visible
// (vtkTiledRayCastEmptySpace). Rays enter the visible part by its own boundary faces and leave
// it where the next tet is invisible.
uniform usamplerBuffer in_visibleTets;

bool trcTetVisible(uint tet)
{
  return (texelFetch(in_visibleTets, int(tet >> 5u)).r & (1u << (tet & 31u))) != 0u;
}
#endif
