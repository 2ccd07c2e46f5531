//============================================================================
// TiledRayCast: the blend modes of vtkVolumeMapper other than compositing,
// exact along each linear segment (compute pipeline). Follows the partial
// pre-integration code, whose node list it evaluates (vtkTiledRayCastTransferFunction:
// opacity = attenuation * unit distance, piecewise linear between nodes), and
// whose trcIntegrate the mapper renames trcIntegrateComposite.
//
// The walk's colour holds an accumulator, its alpha kept 0 (no early ray
// termination); trcFinishRay turns it into the pixel:
//   maximum (1) / minimum (2) intensity: r = the extreme scalar of the ray, g = 1
//     once a segment was seen (a linear segment's extremes are its ends); the
//     pixel is the transfer function there, colour times opacity, as VTK's ray
//     casters give it;
//   average intensity (3): r = the integral of opacity(s) * normalised s along
//     the ray, g = the length integrated, both only where s lies in the average
//     range; the pixel is gray r / g, opaque (VTK's sampled mean, here exact);
//   additive (4): r = the same integral over the whole ray; the pixel is gray
//     r / unit distance, opaque (VTK's sum of samples taken one unit distance
//     apart). The scalar is normalised to [0, 1] over the data's range.
//============================================================================
uniform int in_blendMode;
uniform vec2 in_blendScalarRange; // the data's scalar range, shifted as the scalars are
uniform vec2 in_averageRange;     // the average range, shifted likewise
uniform float in_opacityUnitDistance;

float trcOpacityAt(float s, int below)
{
  vec3 c;
  float tau;
  trcEvaluate(s, below, c, tau);
  return tau * in_opacityUnitDistance;
}

float trcNormalised(float s)
{
  float width = in_blendScalarRange.y - in_blendScalarRange.x;
  return width > 0.0 ? (s - in_blendScalarRange.x) / width : 0.0;
}

// The integral of opacity(s) * normalised s over scalars [lo, hi], split at the transfer
// function's nodes, where opacity is linear: on a piece from p to q with both linear,
// (q - p) (a_p n_p / 3 + (a_p n_q + a_q n_p) / 6 + a_q n_q / 3).
float trcWeightedIntegral(float lo, float hi)
{
  int i = trcFindNode(lo);
  float s = lo;
  float a = trcOpacityAt(lo, i);
  float sum = 0.0;
  for (++i; i < in_transferFunctionNodes; ++i)
  {
    float next = trcNodeScalar(i);
    if (next >= hi)
    {
      break;
    }
    vec3 c;
    float tau;
    trcNode(i, c, tau);
    float b = tau * in_opacityUnitDistance;
    float ns = trcNormalised(s);
    float nn = trcNormalised(next);
    sum += (next - s) * (a * ns / 3.0 + (a * nn + b * ns) / 6.0 + b * nn / 3.0);
    s = next;
    a = b;
  }
  float b = trcOpacityAt(hi, i - 1);
  float ns = trcNormalised(s);
  float nh = trcNormalised(hi);
  return sum + (hi - s) * (a * ns / 3.0 + (a * nh + b * ns) / 6.0 + b * nh / 3.0);
}

void trcIntegrate(float sf, float sb, float d, inout vec4 color)
{
  if (!(d > 0.0) || isnan(sf) || isnan(sb) || isinf(sf) || isinf(sb))
  {
    return; // nothing to integrate, or a tet touching a non-finite scalar: left out
  }
  float lo = min(sf, sb);
  float hi = max(sf, sb);
  if (in_blendMode == 1 || in_blendMode == 2)
  {
    float extreme = in_blendMode == 1 ? hi : lo;
    bool better = in_blendMode == 1 ? extreme > color.r : extreme < color.r;
    color.r = color.g == 0.0 || better ? extreme : color.r;
    color.g = 1.0;
    return;
  }
  float from = lo;
  float to = hi;
  float length = d;
  if (in_blendMode == 3)
  {
    // Only where the scalar lies in the average range: a part of the segment, s being linear.
    from = max(lo, in_averageRange.x);
    to = min(hi, in_averageRange.y);
    if (to < from || (to == from && hi > lo))
    {
      return;
    }
    length = hi > lo ? d * (to - from) / (hi - lo) : d;
  }
  // Along the segment dt = d / (hi - lo) ds; a constant scalar gives opacity * s * d.
  float integral = to > from ? trcWeightedIntegral(from, to) * (length / (to - from))
                             : trcOpacityAt(from, trcFindNode(from)) * trcNormalised(from) * length;
  color.r += integral;
  color.g += length;
}

// The pixel of a ray that entered the mesh, from its accumulator.
vec4 trcFinishRay(vec4 accumulated)
{
  if (in_blendMode == 1 || in_blendMode == 2)
  {
    if (accumulated.g == 0.0)
    {
      return vec4(0.0);
    }
    vec3 c;
    float tau;
    trcEvaluate(accumulated.r, trcFindNode(accumulated.r), c, tau);
    float alpha = clamp(tau * in_opacityUnitDistance, 0.0, 1.0);
    return vec4(c * alpha, alpha);
  }
  if (in_blendMode == 3)
  {
    if (!(accumulated.g > 0.0))
    {
      return vec4(0.0);
    }
    return vec4(vec3(clamp(accumulated.r / accumulated.g, 0.0, 1.0)), 1.0);
  }
  return vec4(vec3(clamp(accumulated.r / in_opacityUnitDistance, 0.0, 1.0)), 1.0);
}
