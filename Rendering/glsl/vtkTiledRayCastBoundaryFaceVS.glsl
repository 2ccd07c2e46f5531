//TRC::Version
//============================================================================
// TiledRayCast: boundary faces for the first-hit and depth-peeling passes.
// No vertex buffer: vertex gl_VertexID is corner (gl_VertexID % 3) of boundary
// face (gl_VertexID / 3), whose points come from the mesh textures.
//============================================================================
//TRC::Common::Dec
//TRC::Layout::Dec

// Boundary faces, (tet << 2) | face.
uniform usamplerBuffer in_boundaryFaces;
// Object (shifted) to clip coordinates.
uniform mat4 in_objectToClip;

flat out uint ip_tet;
flat out int ip_face;

void main()
{
  uint word = texelFetch(in_boundaryFaces, gl_VertexID / 3).r;
  ip_tet = word >> 2u;
  ip_face = int(word & 3u);
  vec3 p = trcTetPoint(ip_tet, trcFacePoints[ip_face][gl_VertexID % 3]);
  gl_Position = in_objectToClip * vec4(p, 1.0);
}
