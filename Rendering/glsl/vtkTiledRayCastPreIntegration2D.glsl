//============================================================================
// TiledRayCast: pre-integration with a 2D table of mean colour and optical
// depth per unit length E over (front scalar, back scalar) for one reference
// length L0. A segment of length d uses alpha' = 1 - exp(-E d) and the mean
// colour times alpha' (the opacity correction of 2D pre-integration, from the
// depth itself: read back from a saturated alpha it was up to 181/255 off on
// near-opaque tets).
// That correction is exact only where the transfer function is constant along
// the segment; stretched over a long segment whose scalar varies it is far off
// (a 24-unit slab of optical depth 6: 150/255 for an exact 92). So an
// optically thick segment (estimated from its own lookup: more than 0.5) is
// split into equal parts of optical depth up to 0.5, but none shorter than L0,
// each looked up with its own end scalars; thin segments, most of a mesh, keep
// their one lookup.
//============================================================================
uniform sampler2D in_preIntegrationTable;
// (first grid scalar, grid scalars per scalar unit, size)
uniform vec3 in_tableScalarMap;
uniform float in_tableReferenceLength;

// Mean colour and optical depth per unit length of a segment of length L0 from
// scalar s0 to s1.
vec4 trcTableLookup(float s0, float s1)
{
  float size = in_tableScalarMap.z;
  vec2 grid = clamp(vec2(s0, s1) - in_tableScalarMap.x, 0.0, 3.4e38) * in_tableScalarMap.y;
  grid = min(grid, vec2(size - 1.0));
  return texture(in_preIntegrationTable, (grid + 0.5) / size);
}

void trcIntegrate(float sf, float sb, float d, inout vec4 color)
{
  if (!(d > 0.0) || isnan(sf) || isnan(sb) || isinf(sf) || isinf(sb))
  {
    return;
  }
  float ratio = d / in_tableReferenceLength;
  vec4 piece = trcTableLookup(sf, sb);
  float depth = piece.a * d;
  // Clamped as floats: a near-opaque segment's depth is far beyond any int.
  int parts = int(clamp(ceil(depth / 0.5), 1.0, max(ceil(ratio), 1.0)));
  float partLength = d / float(parts);
  for (int k = 0; k < parts; ++k)
  {
    if (parts > 1)
    {
      piece = trcTableLookup(
        mix(sf, sb, float(k) / float(parts)), mix(sf, sb, float(k + 1) / float(parts)));
    }
    // Beyond an optical depth of 80 alpha is 1 in float; the cap keeps the product finite.
    float alpha = 1.0 - exp(-min(piece.a * partLength, 80.0));
    color.rgb += (1.0 - color.a) * alpha * piece.rgb;
    color.a += (1.0 - color.a) * alpha;
    if (color.a >= in_earlyTerminationOpacity)
    {
      return;
    }
  }
}
