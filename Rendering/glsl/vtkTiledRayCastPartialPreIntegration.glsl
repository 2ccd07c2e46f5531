//============================================================================
// TiledRayCast: partial pre-integration (Moreland and Angel 2004).
// The transfer function is a list of nodes (s, attenuation, rgb), linear in
// between; a segment is split at every node it crosses and each piece, where
// colour and attenuation are linear, is integrated with the Psi table of
// vtkUnstructuredGridPartialPreIntegration (512 x 512, sampled at
// gamma = tau D / (tau D + 1) = i / 512, read here with bilinear filtering).
//============================================================================
// Two texels per node: (s, attenuation, 0, 0), (r, g, b, 0).
uniform samplerBuffer in_transferFunction;
uniform int in_transferFunctionNodes;
uniform sampler2D in_psiTable;
uniform float in_psiTableSize;

float trcNodeScalar(int i)
{
  return texelFetch(in_transferFunction, 2 * i).x;
}

void trcNode(int i, out vec3 c, out float tau)
{
  tau = texelFetch(in_transferFunction, 2 * i).y;
  c = texelFetch(in_transferFunction, 2 * i + 1).rgb;
}

// Index of the last node at or below s (-1 if s is below every node).
int trcFindNode(float s)
{
  if (s < trcNodeScalar(0))
  {
    return -1;
  }
  int lo = 0;
  int hi = in_transferFunctionNodes;
  while (hi - lo > 1)
  {
    int mid = (lo + hi) >> 1; // both are non-negative: a shift, not a signed division
    if (trcNodeScalar(mid) <= s)
    {
      lo = mid;
    }
    else
    {
      hi = mid;
    }
  }
  return lo;
}

void trcEvaluate(float s, int below, out vec3 c, out float tau)
{
  if (below < 0)
  {
    trcNode(0, c, tau);
    return;
  }
  if (below >= in_transferFunctionNodes - 1)
  {
    trcNode(in_transferFunctionNodes - 1, c, tau);
    return;
  }
  float s0 = trcNodeScalar(below);
  float s1 = trcNodeScalar(below + 1);
  vec3 c0;
  vec3 c1;
  float t0;
  float t1;
  trcNode(below, c0, t0);
  trcNode(below + 1, c1, t1);
  float w = s1 > s0 ? clamp((s - s0) / (s1 - s0), 0.0, 1.0) : 1.0;
  c = mix(c0, c1, w);
  tau = mix(t0, t1, w);
}

float trcPsi(float taufD, float taubD)
{
  // VTK's table is Psi[front][back], row-major: uploaded as a 2D texture, its rows are t and its
  // columns s, so s = gamma_back and t = gamma_front. (Read transposed until this version: exact
  // only where the attenuation was the same at both ends; 1.5/255 RMSE on 5 huge tets.)
  vec2 gamma = vec2(taubD / (taubD + 1.0), taufD / (taufD + 1.0));
  return texture(in_psiTable, (gamma * in_psiTableSize + 0.5) / in_psiTableSize).r;
}

// Composite one piece of length d (world units) where colour and attenuation
// go linearly from (cf, tf) to (cb, tb).
void trcCompositePiece(vec3 cf, float tf, vec3 cb, float tb, float d, inout vec4 color)
{
  float taufD = tf * d;
  float taubD = tb * d;
  float zeta = exp(-0.5 * (taufD + taubD));
  float psi = trcPsi(taufD, taubD);
  vec3 c = cf * (1.0 - psi) + cb * (psi - zeta);
  color.rgb += (1.0 - color.a) * c;
  color.a += (1.0 - color.a) * (1.0 - zeta);
}

void trcIntegrate(float sf, float sb, float d, inout vec4 color)
{
  if (!(d > 0.0) || isnan(sf) || isnan(sb) || isinf(sf) || isinf(sb))
  {
    // Nothing to integrate, or a tet touching a non-finite scalar: transparent.
    return;
  }
  int node = trcFindNode(sf);
  vec3 cf;
  float tf;
  trcEvaluate(sf, node, cf, tf);
  float ds = sb - sf;
  if (ds != 0.0)
  {
    // Walk the nodes strictly between sf and sb, in the ray's direction.
    int step = ds > 0.0 ? 1 : -1;
    int i = ds > 0.0 ? node + 1 : node;
    if (ds < 0.0 && i >= 0 && trcNodeScalar(i) >= sf)
    {
      --i;
    }
    float s = sf;
    for (; i >= 0 && i < in_transferFunctionNodes; i += step)
    {
      float sn = trcNodeScalar(i);
      if ((ds > 0.0 && sn >= sb) || (ds < 0.0 && sn <= sb))
      {
        break;
      }
      vec3 cn;
      float tn;
      trcNode(i, cn, tn);
      trcCompositePiece(cf, tf, cn, tn, d * (sn - s) / ds, color);
      s = sn;
      cf = cn;
      tf = tn;
      if (color.a >= in_earlyTerminationOpacity)
      {
        return;
      }
    }
    // The last node at or below sb, which trcFindNode(sb) would find, from where the walk
    // stopped instead of a second binary search (its dependent fetches are a good part of a
    // step): going down, the node it stopped at; going up, the one before, or nodes equal to sb.
    int below = i;
    if (ds > 0.0)
    {
      below = i - 1;
      while (below + 1 < in_transferFunctionNodes && trcNodeScalar(below + 1) <= sb)
      {
        ++below;
      }
    }
    vec3 cb;
    float tb;
    trcEvaluate(sb, below, cb, tb);
    trcCompositePiece(cf, tf, cb, tb, d * (sb - s) / ds, color);
  }
  else
  {
    trcCompositePiece(cf, tf, cf, tf, d, color);
  }
}
