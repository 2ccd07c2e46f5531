//============================================================================
// TiledRayCast: full pre-integration with a 3D table of mean colour and
// optical depth per unit length over (front scalar, back scalar, length),
// computed exactly on the CPU at the table's grid points and read with
// trilinear filtering (the depth per unit length is the same at every length:
// exact along that axis and for the shortest segments, and it never saturates
// as alpha does; vtkTiledRayCastPreIntegrationTable). Segments longer than the
// table's longest length are split into equal parts.
//============================================================================
uniform sampler3D in_preIntegrationTable;
// (first grid scalar, grid scalars per scalar unit, size)
uniform vec3 in_tableScalarMap;
// (grid lengths per world unit, size, longest length)
uniform vec3 in_tableLengthMap;

void trcIntegrate(float sf, float sb, float d, inout vec4 color)
{
  if (!(d > 0.0) || isnan(sf) || isnan(sb) || isinf(sf) || isinf(sb))
  {
    return;
  }
  int parts = int(ceil(d / in_tableLengthMap.z));
  parts = max(parts, 1);
  float partLength = d / float(parts);
  float size = in_tableScalarMap.z;
  float lengthSize = in_tableLengthMap.y;
  for (int k = 0; k < parts; ++k)
  {
    float s0 = mix(sf, sb, float(k) / float(parts));
    float s1 = mix(sf, sb, float(k + 1) / float(parts));
    vec3 grid = vec3(clamp((s0 - in_tableScalarMap.x) * in_tableScalarMap.y, 0.0, size - 1.0),
      clamp((s1 - in_tableScalarMap.x) * in_tableScalarMap.y, 0.0, size - 1.0),
      clamp(partLength * in_tableLengthMap.x, 0.0, lengthSize - 1.0));
    vec4 piece = texture(in_preIntegrationTable, (grid + 0.5) / vec3(size, size, lengthSize));
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
