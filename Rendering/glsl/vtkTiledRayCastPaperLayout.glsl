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
// The walk finds the entry face as the one shared with the tet it came from.
const bool TRC_LAYOUT_STORES_ENTRY_FACES = false;

ivec2 trcPaperTexel(uint tet)
{
  int t = int(tet);
  return ivec2(t % in_paperWidth, 3 * (t / in_paperWidth));
}

// Four vectors packed in a tet's three texels of one texture:
// (v0.xyz, v3.x) (v1.xyz, v3.y) (v2.xyz, v3.z).
void trcPaperUnpack(sampler2D source, ivec2 c, out vec3 v[4])
{
  vec4 t0 = texelFetch(source, c, 0);
  vec4 t1 = texelFetch(source, c + ivec2(0, 1), 0);
  vec4 t2 = texelFetch(source, c + ivec2(0, 2), 0);
  v[0] = t0.xyz;
  v[1] = t1.xyz;
  v[2] = t2.xyz;
  v[3] = vec3(t0.w, t1.w, t2.w);
}

// The four points of a tet.
void trcTetPoints(uint tet, out vec3 p[4])
{
  trcPaperUnpack(in_Vertices, trcPaperTexel(tet), p);
}

// A tet as the walk holds it: points, the stored outward face normals and the field.
struct TrcTet
{
  vec3 p[4];
  vec3 n[4];
  vec4 field;
};

void trcLoadTet(uint tet, out TrcTet t)
{
  ivec2 c = trcPaperTexel(tet);
  trcPaperUnpack(in_Vertices, c, t.p);
  trcPaperUnpack(in_FaceNormals, c, t.n);
  t.field = texelFetch(in_NeighborsAndScalars, c + ivec2(0, 2), 0);
}

vec3 trcFaceNormal(TrcTet t, int f)
{
  return t.n[f];
}

// A point of face `face` and its outward normal (the first-hit and entry passes need no more).
void trcLoadFace(uint tet, int face, out vec3 point, out vec3 normal)
{
  ivec2 c = trcPaperTexel(tet);
  vec3 p[4];
  vec3 n[4];
  trcPaperUnpack(in_Vertices, c, p);
  trcPaperUnpack(in_FaceNormals, c, n);
  point = p[trcFacePoints[face].x];
  normal = n[face];
}

uint trcPaperTet(vec2 uv)
{
  if (uv.x < 0.0)
  {
    return TRC_NO_NEIGHBOR;
  }
  return uint(int(uv.y) / 3 * in_paperWidth + int(uv.x));
}

// The paper's layout stores neighbours as texel coordinates: the words are the neighbours'
// tet indices (TRC_NO_NEIGHBOR for none), and no entry face.
uvec4 trcLoadNeighborWords(uint tet)
{
  ivec2 c = trcPaperTexel(tet);
  vec4 a01 = texelFetch(in_NeighborsAndScalars, c, 0);
  vec4 a23 = texelFetch(in_NeighborsAndScalars, c + ivec2(0, 1), 0);
  return uvec4(trcPaperTet(a01.xy), trcPaperTet(a01.zw), trcPaperTet(a23.xy), trcPaperTet(a23.zw));
}

uint trcNeighborTet(uvec4 words, int f)
{
  return words[f];
}

int trcNeighborFace(uvec4 words, int f)
{
  return TRC_FACE_FROM_PREVIOUS;
}
