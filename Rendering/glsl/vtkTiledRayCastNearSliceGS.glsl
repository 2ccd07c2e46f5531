//TRC::Version
//============================================================================
// TiledRayCast: the cross-section of a tet with the near plane, as one or two
// triangles, so that rays whose near-plane point lies inside the mesh start in
// the tet that holds it. Each edge's crossing is computed from its two end
// points in a fixed order (by coordinates), so the two tets sharing an edge
// compute the same point and the slices tile the plane without cracks.
//============================================================================
//TRC::Common::Dec
//TRC::Layout::Dec

layout(points) in;
layout(triangle_strip, max_vertices = 4) out;

flat in uint ip_vertexTet[];
flat out uint ip_tet;

// The near plane in object coordinates: dot(in_nearPlane.xyz, x) + in_nearPlane.w,
// positive beyond the plane (in front of the camera).
uniform vec4 in_nearPlane;
uniform mat4 in_objectToClip;

bool trcBefore(vec3 a, vec3 b)
{
  return a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && a.z < b.z)));
}

vec3 trcCrossing(vec3 a, float da, vec3 b, float db)
{
  if (trcBefore(b, a))
  {
    return b + (db / (db - da)) * (a - b);
  }
  return a + (da / (da - db)) * (b - a);
}

void trcEmit(vec3 q)
{
  vec4 clip = in_objectToClip * vec4(q, 1.0);
  // The slice lies on the near plane itself, where rounding would let the clipper cut it away in
  // places: move it to the middle of the depth range (the fragment shader writes its own depth).
  gl_Position = vec4(clip.xy, 0.0, clip.w);
  EmitVertex();
}

void main()
{
  uint tet = ip_vertexTet[0];
#ifdef TRC_SKIP_EMPTY_SPACE
  if (!trcTetVisible(tet))
  {
    return; // rays from here start at the visible part's faces behind
  }
#endif
  vec3 p[4];
  trcTetPoints(tet, p);
  float d[4];
  int below = 0;
  for (int i = 0; i < 4; ++i)
  {
    d[i] = dot(in_nearPlane.xyz, p[i]) + in_nearPlane.w;
    below += d[i] < 0.0 ? 1 : 0;
  }
  if (below == 0 || below == 4)
  {
    return;
  }
  ip_tet = tet;
  // Split the points into the two sides.
  int side0[4];
  int side1[4];
  int n0 = 0;
  int n1 = 0;
  for (int i = 0; i < 4; ++i)
  {
    if (d[i] < 0.0)
    {
      side0[n0++] = i;
    }
    else
    {
      side1[n1++] = i;
    }
  }
  if (n0 == 1 || n1 == 1)
  {
    // One point alone on its side: a triangle.
    int lone = n0 == 1 ? side0[0] : side1[0];
    for (int k = 0; k < 3; ++k)
    {
      int o = n0 == 1 ? side1[k] : side0[k];
      trcEmit(trcCrossing(p[lone], d[lone], p[o], d[o]));
    }
  }
  else
  {
    // Two and two: a quad (a,c) (a,d) (b,c) (b,d) as a strip.
    int a = side0[0];
    int b = side0[1];
    int c = side1[0];
    int e = side1[1];
    trcEmit(trcCrossing(p[a], d[a], p[c], d[c]));
    trcEmit(trcCrossing(p[a], d[a], p[e], d[e]));
    trcEmit(trcCrossing(p[b], d[b], p[c], d[c]));
    trcEmit(trcCrossing(p[b], d[b], p[e], d[e]));
  }
  EndPrimitive();
}
