//============================================================================
// TiledRayCast: mesh access for the compact layout (vtkTetMeshCompactLayout).
// Per tet: point ids (RGBA32UI) and neighbours (RGBA32UI, (n << 2) | face in n,
// or TRC_NO_NEIGHBOR); per point: (x, y, z, scalar) in RGBA32F. Normals and
// the linear scalar field are computed here, from the four points.
//============================================================================
uniform usamplerBuffer in_TetPoints;
uniform usamplerBuffer in_TetNeighbors;
uniform samplerBuffer in_Points;
//TRC::CellScalars::Dec

// The four points of a tet (its point ids, then the points).
void trcTetPoints(uint tet, out vec3 p[4])
{
  uvec4 ids = texelFetch(in_TetPoints, int(tet));
  p[0] = texelFetch(in_Points, int(ids.x)).xyz;
  p[1] = texelFetch(in_Points, int(ids.y)).xyz;
  p[2] = texelFetch(in_Points, int(ids.z)).xyz;
  p[3] = texelFetch(in_Points, int(ids.w)).xyz;
}

// Points, outward face normals (not normalised) and the scalar field
// s(x) = dot(field.xyz, x) + field.w of one tet.
void trcLoadTet(uint tet, out vec3 p[4], out vec3 n[4], out vec4 field)
{
  uvec4 ids = texelFetch(in_TetPoints, int(tet));
  vec4 q0 = texelFetch(in_Points, int(ids.x));
  vec4 q1 = texelFetch(in_Points, int(ids.y));
  vec4 q2 = texelFetch(in_Points, int(ids.z));
  vec4 q3 = texelFetch(in_Points, int(ids.w));
  p[0] = q0.xyz;
  p[1] = q1.xyz;
  p[2] = q2.xyz;
  p[3] = q3.xyz;
  vec3 e1 = p[1] - p[0];
  vec3 e2 = p[2] - p[0];
  vec3 e3 = p[3] - p[0];
  n[0] = cross(p[2] - p[1], p[3] - p[1]);
  n[1] = cross(e3, e2);
  n[2] = cross(e1, e3);
  n[3] = cross(e2, e1);
  //TRC::CellScalars::Impl
  // The gradient of the linear interpolant: grad(b_i) = -n_i / det for a
  // positively oriented tet, so grad(s) = -(sum s_i n_i) / det.
  float det = dot(e1, cross(e2, e3));
  vec3 weighted = q0.w * n[0] + q1.w * n[1] + q2.w * n[2] + q3.w * n[3];
  // A degenerate tet holds no volume: any field will do, but it must be finite.
  float scale = dot(e1, e1) + dot(e2, e2) + dot(e3, e3);
  vec3 g = abs(det) > 1e-12 * scale * sqrt(scale) ? -weighted / det : vec3(0.0);
  field = vec4(g, 0.25 * (q0.w + q1.w + q2.w + q3.w) - dot(g, 0.25 * (p[0] + p[1] + p[2] + p[3])));
}

// A point of face `face` and its outward normal, as trcLoadTet computes it (the first-hit and
// entry passes need no more: three points instead of four, no gradient).
void trcLoadFace(uint tet, int face, out vec3 point, out vec3 normal)
{
  uvec4 ids = texelFetch(in_TetPoints, int(tet));
  ivec3 corners = trcFacePoints[face];
  vec3 a = texelFetch(in_Points, int(ids[corners.x])).xyz;
  vec3 b = texelFetch(in_Points, int(ids[corners.y])).xyz;
  vec3 c = texelFetch(in_Points, int(ids[corners.z])).xyz;
  point = a;
  normal = cross(b - a, c - a);
}

// Neighbour tet across each face and the index of the shared face in it.
void trcLoadNeighbors(uint tet, out uvec4 tets, out ivec4 faces)
{
  uvec4 words = texelFetch(in_TetNeighbors, int(tet));
  tets = words >> 2u;
  faces = ivec4(words & 3u);
  tets.x = words.x == TRC_NO_NEIGHBOR ? TRC_NO_NEIGHBOR : tets.x;
  tets.y = words.y == TRC_NO_NEIGHBOR ? TRC_NO_NEIGHBOR : tets.y;
  tets.z = words.z == TRC_NO_NEIGHBOR ? TRC_NO_NEIGHBOR : tets.z;
  tets.w = words.w == TRC_NO_NEIGHBOR ? TRC_NO_NEIGHBOR : tets.w;
}
