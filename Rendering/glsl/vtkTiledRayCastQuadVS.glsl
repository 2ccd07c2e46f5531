//TRC::Version
//============================================================================
// TiledRayCast: a screen-aligned rectangle (a tile, or the whole viewport) in
// NDC, drawn as a 4-vertex triangle strip with no vertex buffer.
//============================================================================
// (x0, y0, x1, y1) in NDC
uniform vec4 in_rectangle;
uniform float in_rectangleDepth;

void main()
{
  vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);
  gl_Position = vec4(mix(in_rectangle.xy, in_rectangle.zw, corner), in_rectangleDepth, 1.0);
}
