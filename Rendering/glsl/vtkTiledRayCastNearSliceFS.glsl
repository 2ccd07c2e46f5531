//TRC::Version
//============================================================================
// TiledRayCast: rays that start inside the mesh, at the near plane.
//============================================================================
//TRC::Common::Dec

flat in uint ip_tet;

//TRC::EntryTarget::Dec

void main()
{
  TrcRay ray = trcPixelRay(gl_FragCoord.xy);
  if (in_lambdaNear >= ray.lambdaMax || ray.lambdaMin >= ray.lambdaMax)
  {
    discard;
  }
#ifdef TRC_ENTRY_LIST
  // Listed as a near-plane entry: the traversal starts there before any boundary face.
  trcAppendEntry(ivec2(gl_FragCoord.xy), in_lambdaNear, ip_tet << 2u, true);
#else
  // Depth 0: a ray that starts at the near plane wins over every boundary face.
  gl_FragDepth = 0.0;
  fragOutput0 = trcPackState(ip_tet, in_lambdaNear, TRC_ACTIVE, TRC_NO_FACE);
  fragOutput1 = vec4(0.0);
  fragOutput2 = trcPackEntry(in_lambdaNear, TRC_NEAR_PLANE_KEY);
#endif
}
