#version 430 core
//============================================================================
// TiledRayCast: a deforming mesh's new points, from the input's coordinates
// straight into the compact layout's point texels (vtkTiledRayCastPointMotion).
// Two programs from this source:
// - TRC_MOTION_CHECK: every tetrahedron classified as a full build would
//   classify it (vtkTetMeshOrientation::Classify, the same arithmetic in double
//   precision, no fused multiply-adds), against the flags the mesh holds: any
//   that turned inside out, became flat or stopped being flat is counted, and
//   so is any coordinate that is not finite (the CPU then rebuilds the mesh).
//   The longest edge comes with it, rounded up to a float, squared.
// - otherwise: each mesh point's coordinates (the input's point in the
//   builder's point order) less the shift, in float, into x, y, z of its texel;
//   w, the point scalar, stays.
//============================================================================
//TRC::Defines
layout(local_size_x = 256) in;

#ifdef TRC_INPUT_DOUBLE
#define TrcCoordinate double
#else
#define TrcCoordinate float
#endif

layout(std430, binding = 0) readonly buffer InputPoints
{
  TrcCoordinate in_points[];
};
// The input point of each mesh point (the builder's point order); unread when in_ordered is 0.
layout(std430, binding = 1) readonly buffer PointOrder
{
  uint in_order[];
};
// The shift (the centre of the new bounds) and the degeneracy tolerance in, the findings out.
layout(std430, binding = 2) buffer Motion
{
  double in_shift[3];
  double in_tolerance;
  uint out_changed;
  uint out_nonFinite;
  uint out_longest2;
};
#ifdef TRC_MOTION_CHECK
layout(std430, binding = 3) readonly buffer TetPoints
{
  uvec4 in_tetPoints[];
};
// The mesh's flags (vtkTetMesh::TetFlags), four bytes to a word.
layout(std430, binding = 4) readonly buffer TetFlags
{
  uint in_flags[];
};
uniform int in_firstTet;
uniform int in_tetCount;
#else
// The compact layout's point texels (x, y, z, scalar), the part from in_firstPoint on.
layout(std430, binding = 3) buffer MeshPoints
{
  float out_points[];
};
uniform int in_firstPoint;
#endif
uniform int in_pointCount;
uniform int in_ordered;

int trcInvocation()
{
  return int(gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * 256u);
}

dvec3 trcInputPoint(int point)
{
  return dvec3(in_points[3 * point], in_points[3 * point + 1], in_points[3 * point + 2]);
}

dvec3 trcMeshPoint(uint point)
{
  return trcInputPoint(int(in_ordered != 0 ? in_order[point] : point));
}

#ifdef TRC_MOTION_CHECK
// vtkMath::Dot and vtkMath::Cross, operation for operation.
double trcDot(dvec3 a, dvec3 b)
{
  precise double d = a.x * b.x + a.y * b.y + a.z * b.z;
  return d;
}

void main()
{
  int i = trcInvocation();
  if (i < in_pointCount)
  {
    dvec3 p = trcInputPoint(i);
    if (any(isnan(p)) || any(isinf(p)))
    {
      atomicAdd(out_nonFinite, 1u);
    }
  }
  if (i >= in_tetCount)
  {
    return;
  }
  int tet = in_firstTet + i;
  uvec4 ids = in_tetPoints[i];
  dvec3 p0 = trcMeshPoint(ids.x);
  dvec3 p1 = trcMeshPoint(ids.y);
  dvec3 p2 = trcMeshPoint(ids.z);
  dvec3 p3 = trcMeshPoint(ids.w);
  precise dvec3 e1 = p1 - p0;
  precise dvec3 e2 = p2 - p0;
  precise dvec3 e3 = p3 - p0;
  precise dvec3 c =
    dvec3(e2.y * e3.z - e2.z * e3.y, e2.z * e3.x - e2.x * e3.z, e2.x * e3.y - e2.y * e3.x);
  precise double det = trcDot(e1, c);
  precise dvec3 e4 = p2 - p1;
  precise dvec3 e5 = p3 - p1;
  precise dvec3 e6 = p3 - p2;
  double l2 = max(max(max(trcDot(e1, e1), trcDot(e2, e2)), max(trcDot(e3, e3), trcDot(e4, e4))),
    max(trcDot(e5, e5), trcDot(e6, e6)));
  precise double l3 = l2 * sqrt(l2);
  bool degenerate = abs(det) <= in_tolerance * l3;
  uint flags = (in_flags[tet >> 2] >> (8u * uint(tet & 3))) & 0xFFu;
  bool swapped = (flags & TRC_FLAG_INVERTED) != 0u;
  bool wantSwap = (swapped ? -det : det) < 0.0LF && !degenerate;
  bool wasDegenerate = (flags & TRC_FLAG_DEGENERATE) != 0u;
  if (wantSwap != swapped || degenerate != wasDegenerate)
  {
    atomicAdd(out_changed, 1u);
  }
  // The longest edge, squared, as a float no shorter than it: the tables then cover it.
  float f = float(l2);
  uint bits = floatBitsToUint(f);
  if (double(f) < l2)
  {
    bits += 1u;
  }
  atomicMax(out_longest2, bits);
}
#else
void main()
{
  int i = trcInvocation();
  if (i >= in_pointCount)
  {
    return;
  }
  dvec3 p = trcMeshPoint(uint(in_firstPoint + i));
  out_points[4 * i] = float(p.x - in_shift[0]);
  out_points[4 * i + 1] = float(p.y - in_shift[1]);
  out_points[4 * i + 2] = float(p.z - in_shift[2]);
}
#endif
