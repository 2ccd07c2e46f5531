//============================================================================
// TiledRayCast: pre-integration with a 2D table of premultiplied colour and
// opacity over (front scalar, back scalar) for one reference length L0. A
// segment of length d uses alpha' = 1 - (1 - alpha)^(d / L0) and the colour
// scaled by alpha' / alpha (the opacity correction of 2D pre-integration).
//============================================================================
uniform sampler2D in_preIntegrationTable;
// (first grid scalar, grid scalars per scalar unit, size)
uniform vec3 in_tableScalarMap;
uniform float in_tableReferenceLength;

void trcIntegrate(float sf, float sb, float d, inout vec4 color)
{
  if (!(d > 0.0) || isnan(sf) || isnan(sb) || isinf(sf) || isinf(sb))
  {
    return;
  }
  float size = in_tableScalarMap.z;
  vec2 grid = clamp(vec2(sf, sb) - in_tableScalarMap.x, 0.0, 3.4e38) * in_tableScalarMap.y;
  grid = min(grid, vec2(size - 1.0));
  vec4 piece = texture(in_preIntegrationTable, (grid + 0.5) / size);
  float ratio = d / in_tableReferenceLength;
  float alpha = 1.0 - pow(max(1.0 - piece.a, 0.0), ratio);
  vec3 c = piece.a > 1e-6 ? piece.rgb * (alpha / piece.a) : piece.rgb * ratio;
  color.rgb += (1.0 - color.a) * c;
  color.a += (1.0 - color.a) * alpha;
}
