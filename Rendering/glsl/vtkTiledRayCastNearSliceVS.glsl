//TRC::Version
//============================================================================
// TiledRayCast: one point per tet, for the geometry shader that cuts tets by
// the near plane (camera inside the mesh).
//============================================================================
flat out uint ip_vertexTet;

void main()
{
  ip_vertexTet = uint(gl_VertexID);
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
