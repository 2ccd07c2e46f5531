//TRC::Version
//============================================================================
// TiledRayCast: boundary faces for the first-hit and depth-peeling passes.
// No vertex buffer: vertex gl_VertexID is corner (gl_VertexID % 3) of boundary
// face (gl_VertexID / 3), whose points come from the mesh textures.
//
// Exact coverage: the rasteriser snaps corners to its sub-pixel grid (1/256 px),
// so a pixel centre within that of an edge may land in the wrong face. Where the
// boundary folds (a back face and the front face behind it share a point) no
// front face of the deeper sheet may then cover the pixel, and peeling loses the
// rest of the ray. So each face is grown by in_coverageDilation pixels here and
// the fragment shader keeps exactly the pixels whose centre lies in the face,
// tested against the unsnapped corners passed on below.
//============================================================================
//TRC::Common::Dec
//TRC::Layout::Dec

// Boundary faces, (tet << 2) | face.
uniform usamplerBuffer in_boundaryFaces;
// Object (shifted) to clip coordinates.
uniform mat4 in_objectToClip;
// How far each edge moves outwards, in pixels (0: rasterise the face as it is).
uniform float in_coverageDilation;

flat out uint ip_tet;
flat out int ip_face;
// The face's corners in pixels of the viewport, unsnapped, and whether they are
// valid (every corner in front of the eye).
flat out vec2 ip_corner0;
flat out vec2 ip_corner1;
flat out vec2 ip_corner2;
flat out int ip_testCoverage;

void main()
{
  uint word = texelFetch(in_boundaryFaces, gl_VertexID / 3).r;
  ip_tet = word >> 2u;
  ip_face = int(word & 3u);
  ivec3 points = trcFacePoints[ip_face];
  vec3 p[4];
  trcTetPoints(ip_tet, p);
  vec4 c0 = in_objectToClip * vec4(p[points.x], 1.0);
  vec4 c1 = in_objectToClip * vec4(p[points.y], 1.0);
  vec4 c2 = in_objectToClip * vec4(p[points.z], 1.0);
  int corner = gl_VertexID % 3;
  gl_Position = corner == 0 ? c0 : (corner == 1 ? c1 : c2);
  ip_corner0 = vec2(0.0);
  ip_corner1 = vec2(0.0);
  ip_corner2 = vec2(0.0);
  ip_testCoverage = 0;
  // A face that crosses the eye's plane is clipped by the rasteriser: left as it is.
  if (in_coverageDilation <= 0.0 || min(c0.w, min(c1.w, c2.w)) <= 0.0)
  {
    return;
  }
  ip_corner0 = (0.5 * c0.xy / c0.w + 0.5) * in_viewportSize;
  ip_corner1 = (0.5 * c1.xy / c1.w + 0.5) * in_viewportSize;
  ip_corner2 = (0.5 * c2.xy / c2.w + 0.5) * in_viewportSize;
  ip_testCoverage = 1;

  // Move this corner so that both of its edges move outwards by the dilation:
  // offset = d (n1 + n2) / (1 + n1.n2) for the edges' unit outward normals. At an
  // acute corner (a face seen almost edge on) the offset is long, 258 d = 4 px at
  // most: the extra pixels cost a fragment each and fail the exact test.
  vec2 previous = corner == 0 ? ip_corner2 : (corner == 1 ? ip_corner0 : ip_corner1);
  vec2 here = corner == 0 ? ip_corner0 : (corner == 1 ? ip_corner1 : ip_corner2);
  vec2 next = corner == 0 ? ip_corner1 : (corner == 1 ? ip_corner2 : ip_corner0);
  vec2 e1 = here - previous;
  vec2 e2 = next - here;
  float area = e1.x * e2.y - e1.y * e2.x;
  float l1 = length(e1);
  float l2 = length(e2);
  if (area == 0.0 || l1 == 0.0 || l2 == 0.0)
  {
    return; // no area on screen: nothing to cover
  }
  float side = area > 0.0 ? 1.0 : -1.0;
  vec2 n1 = side * vec2(e1.y, -e1.x) / l1;
  vec2 n2 = side * vec2(e2.y, -e2.x) / l2;
  vec2 offset = in_coverageDilation * (n1 + n2) / max(1.0 + dot(n1, n2), 3e-5);
  gl_Position.xy += 2.0 * offset / in_viewportSize * gl_Position.w;
}
