//============================================================================
// TiledRayCast: mesh access for the compact layout (vtkTetMeshCompactLayout).
// Per tet: point ids (RGBA32UI) and neighbours (RGBA32UI, (n << 2) | face in n,
// or TRC_NO_NEIGHBOR); per point: (x, y, z, scalar) in RGBA32F. Normals and
// the linear scalar field are computed here, from the four points.
//============================================================================
// A neighbour word holds the face the walk enters by: the walk need not remember the tet it
// came from (a register through every step).
const bool TRC_LAYOUT_STORES_ENTRY_FACES = true;
// The texture buffers and how texel i of each array is read: trcFetchTetPoints(i),
// trcFetchTetNeighbors(i), trcFetchPoints(i) (and trcFetchTetScalars(i) with cell scalars), from
// one texture buffer, or from several where an array is larger than the GPU's largest
// (vtkTiledRayCastShaderComposition writes them).
//TRC::MeshFetch::Dec

// The four points of a tet (its point ids, then the points).
void trcTetPoints(uint tet, out vec3 p[4])
{
  uvec4 ids = trcFetchTetPoints(tet);
  p[0] = trcFetchPoints(ids.x).xyz;
  p[1] = trcFetchPoints(ids.y).xyz;
  p[2] = trcFetchPoints(ids.z).xyz;
  p[3] = trcFetchPoints(ids.w).xyz;
}

// A tet as the walk holds it: its points and the scalar field
// s(x) = dot(field.xyz, x) + field.w. Face normals are computed where the walk uses them
// (trcFaceNormal): four of them held through the step would take twelve registers.
struct TrcTet
{
  vec3 p[4];
  vec4 field;
};

void trcLoadTet(uint tet, out TrcTet t)
{
  uvec4 ids = trcFetchTetPoints(tet);
  vec4 q0 = trcFetchPoints(ids.x);
  vec4 q1 = trcFetchPoints(ids.y);
  vec4 q2 = trcFetchPoints(ids.z);
  vec4 q3 = trcFetchPoints(ids.w);
  t.p[0] = q0.xyz;
  t.p[1] = q1.xyz;
  t.p[2] = q2.xyz;
  t.p[3] = q3.xyz;
  //TRC::CellScalars::Impl
  // The gradient of the linear interpolant from the edges e_i = p_i - p_0 and the scalar
  // differences along them: grad(s) = sum_i (s_i - s_0) (e_j x e_k) / det, (i, j, k) cyclic.
  vec3 e1 = t.p[1] - t.p[0];
  vec3 e2 = t.p[2] - t.p[0];
  vec3 e3 = t.p[3] - t.p[0];
  vec3 c23 = cross(e2, e3);
  float det = dot(e1, c23);
  vec3 weighted = (q1.w - q0.w) * c23 + (q2.w - q0.w) * cross(e3, e1) + (q3.w - q0.w) * cross(e1, e2);
  // A degenerate tet holds no volume: any field will do, but it must be finite.
  float scale = dot(e1, e1) + dot(e2, e2) + dot(e3, e3);
  vec3 g = abs(det) > 1e-12 * scale * sqrt(scale) ? weighted / det : vec3(0.0);
  t.field = vec4(g,
    0.25 * (q0.w + q1.w + q2.w + q3.w) - dot(g, 0.25 * (t.p[0] + t.p[1] + t.p[2] + t.p[3])));
}

// The outward normal (not normalised) of face f, opposite point f; f is a constant where the
// walk calls this (its loop over faces is unrolled), so only one cross product is made.
vec3 trcFaceNormal(TrcTet t, int f)
{
  if (f == 0)
  {
    return cross(t.p[2] - t.p[1], t.p[3] - t.p[1]);
  }
  vec3 e1 = t.p[1] - t.p[0];
  vec3 e2 = t.p[2] - t.p[0];
  vec3 e3 = t.p[3] - t.p[0];
  return f == 1 ? cross(e3, e2) : (f == 2 ? cross(e1, e3) : cross(e2, e1));
}

// A point of face `face` and its outward normal, as trcLoadTet computes it (the first-hit and
// entry passes need no more: three points instead of four, no gradient).
void trcLoadFace(uint tet, int face, out vec3 point, out vec3 normal)
{
  uvec4 ids = trcFetchTetPoints(tet);
  ivec3 corners = trcFacePoints[face];
  vec3 a = trcFetchPoints(ids[corners.x]).xyz;
  vec3 b = trcFetchPoints(ids[corners.y]).xyz;
  vec3 c = trcFetchPoints(ids[corners.z]).xyz;
  point = a;
  normal = cross(b - a, c - a);
}

// The neighbour words of a tet, ((n << 2) | face in n) or TRC_NO_NEIGHBOR per face, read as
// they are stored: the walk decodes only the word of the face it leaves through (four decoded
// neighbours and four faces would hold eight registers through the step).
uvec4 trcLoadNeighborWords(uint tet)
{
  return trcFetchTetNeighbors(tet);
}

// The neighbour across face f, or TRC_NO_NEIGHBOR.
uint trcNeighborTet(uvec4 words, int f)
{
  uint word = words[f];
  return word == TRC_NO_NEIGHBOR ? TRC_NO_NEIGHBOR : word >> 2u;
}

// The index of face f in the neighbour across it.
int trcNeighborFace(uvec4 words, int f)
{
  return int(words[f] & 3u);
}
