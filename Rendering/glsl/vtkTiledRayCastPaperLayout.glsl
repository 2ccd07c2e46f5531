//============================================================================
// TiledRayCast: mesh access for the paper's layout (Bernardon et al. 2004,
// Figure 8; vtkTetMeshPaperLayout). Tet t has three texels in each of three
// RGBA32F 2D textures, at column t % W and rows 3 (t / W) + 0..2:
//   vertices:  (v0.xyz, v3.x) (v1.xyz, v3.y) (v2.xyz, v3.z)
//   normals:   (n0.xyz, n3.x) (n1.xyz, n3.y) (n2.xyz, n3.z)   (outward)
//   neighbours + scalar: (a0.uv, a1.uv) (a2.uv, a3.uv) (g.xyz, c)
// where a neighbour is stored as its texel coordinates (u, v), (-1, -1) for
// none. The paper stores no entry face: the traversal finds it as the face
// shared with the tet it came from.
//============================================================================
uniform sampler2D in_Vertices;
uniform sampler2D in_FaceNormals;
uniform sampler2D in_NeighborsAndScalars;
uniform int in_paperWidth;

ivec2 trcPaperTexel(uint tet)
{
  int t = int(tet);
  return ivec2(t % in_paperWidth, 3 * (t / in_paperWidth));
}

// The four points of a tet (three texels).
void trcTetPoints(uint tet, out vec3 p[4])
{
  ivec2 c = trcPaperTexel(tet);
  vec4 v0 = texelFetch(in_Vertices, c, 0);
  vec4 v1 = texelFetch(in_Vertices, c + ivec2(0, 1), 0);
  vec4 v2 = texelFetch(in_Vertices, c + ivec2(0, 2), 0);
  p[0] = v0.xyz;
  p[1] = v1.xyz;
  p[2] = v2.xyz;
  p[3] = vec3(v0.w, v1.w, v2.w);
}

void trcLoadTet(uint tet, out vec3 p[4], out vec3 n[4], out vec4 field)
{
  trcTetPoints(tet, p);
  ivec2 c = trcPaperTexel(tet);
  vec4 m0 = texelFetch(in_FaceNormals, c, 0);
  vec4 m1 = texelFetch(in_FaceNormals, c + ivec2(0, 1), 0);
  vec4 m2 = texelFetch(in_FaceNormals, c + ivec2(0, 2), 0);
  n[0] = m0.xyz;
  n[1] = m1.xyz;
  n[2] = m2.xyz;
  n[3] = vec3(m0.w, m1.w, m2.w);
  field = texelFetch(in_NeighborsAndScalars, c + ivec2(0, 2), 0);
}

uint trcPaperTet(vec2 uv)
{
  if (uv.x < 0.0)
  {
    return TRC_NO_NEIGHBOR;
  }
  return uint(int(uv.y) / 3 * in_paperWidth + int(uv.x));
}

void trcLoadNeighbors(uint tet, out uvec4 tets, out ivec4 faces)
{
  ivec2 c = trcPaperTexel(tet);
  vec4 a01 = texelFetch(in_NeighborsAndScalars, c, 0);
  vec4 a23 = texelFetch(in_NeighborsAndScalars, c + ivec2(0, 1), 0);
  tets = uvec4(trcPaperTet(a01.xy), trcPaperTet(a01.zw), trcPaperTet(a23.xy), trcPaperTet(a23.zw));
  faces = ivec4(TRC_FACE_FROM_PREVIOUS);
}
