//============================================================================
// TiledRayCast, compute pipeline: taking part in VTK's dual depth peeling
// (vtkRenderer::UseDepthPeelingForVolumes, vtkDualDepthPeelingPass). The pass
// draws the volume once per stage of its peeling and asks, per pixel, for the
// volume between depths it holds in its own textures: in front of the nearest
// translucent fragment not peeled yet, and behind the farthest. Its own
// textures are bound to the samplers below by vtkDualDepthPeelingPass's
// SetShaderParameters, under the names its image ray caster uses, and this file
// reads them as that caster's shader replacements do (VTK 9.1), so that both
// kinds of volume take part alike:
//
// TRC_PEEL_STAGE 1 (outside the translucent range, before the first peel):
//   outerDepthTex (-1, opaque depth) or (-1, -1) without opaque geometry,
//   innerDepthTex (-nearest, farthest) translucent depth or the same as outer;
//   front: from the near plane to the nearest translucent fragment, back: from
//   the farthest to the opaque depth (or the far plane).
// TRC_PEEL_STAGE 2 (a peel): outerDepthTex holds the previous peel's range,
//   innerDepthTex this peel's; front: from the previous nearest to this
//   nearest, back: from this farthest to the previous farthest. A pixel whose
//   range is done (outer.x == -1) is left alone.
// TRC_PEEL_STAGE 3 (the remainder after the last peel, alpha blended):
//   depthRangeTex; one range, the whole remainder.
//
// Depths are window depths in [0, 1]; a range is empty when its start is not
// before its end.
//============================================================================
#if TRC_PEEL_STAGE == 1
uniform sampler2D outerDepthTex;
uniform sampler2D innerDepthTex;
#elif TRC_PEEL_STAGE == 2
uniform sampler2D outerDepthTex;
uniform sampler2D innerDepthTex;
uniform sampler2D opaqueDepthTex;
#else
uniform sampler2D depthRangeTex;
#endif

const vec2 TRC_EMPTY_RANGE = vec2(1.0, -1.0);

// Whether the pass has nothing left for this pixel at this stage (its own ray caster discards it).
bool trcPeelPixelDone(ivec2 pixel)
{
#if TRC_PEEL_STAGE == 1
  return false;
#elif TRC_PEEL_STAGE == 2
  return texelFetch(outerDepthTex, pixel, 0).x == -1.0;
#else
  return texelFetch(depthRangeTex, pixel, 0).x == -1.0;
#endif
}

// The front range (xy) and the back range (zw) the pass asks for at this pixel. At stage 1 the
// back range only counts while the front leaves the ray below the early termination opacity.
vec4 trcPeelRanges(ivec2 pixel)
{
  vec2 front = TRC_EMPTY_RANGE;
  vec2 back = TRC_EMPTY_RANGE;
#if TRC_PEEL_STAGE == 1
  vec2 inner = texelFetch(innerDepthTex, pixel, 0).xy;
  vec2 outer = texelFetch(outerDepthTex, pixel, 0).xy;
  bool opaque = outer.y >= 0.0;
  bool translucent = inner.x != -1.0;
  if (!opaque && !translucent)
  {
    back = vec2(0.0, 1.0);
  }
  else if (!translucent)
  {
    back = vec2(0.0, inner.y);
  }
  else
  {
    front = vec2(0.0, -inner.x);
    back = vec2(inner.y, opaque ? outer.y : 1.0);
  }
#elif TRC_PEEL_STAGE == 2
  vec2 inner = texelFetch(innerDepthTex, pixel, 0).xy;
  vec2 outer = texelFetch(outerDepthTex, pixel, 0).xy;
  float frontEnd = -inner.x;
  // The same range in front and behind: only the back one is drawn.
  bool onlyBack = -outer.x == inner.y && frontEnd == outer.y;
  bool noInner = inner.x == -1.0;
  if (noInner)
  {
    frontEnd = outer.y;
  }
  float opaqueDepth = texelFetch(opaqueDepthTex, pixel, 0).x;
  bool endBehindOpaque = frontEnd >= opaqueDepth;
  if (!onlyBack)
  {
    front = vec2(-outer.x, endBehindOpaque ? opaqueDepth : frontEnd);
  }
  if (!endBehindOpaque && !noInner)
  {
    back = vec2(inner.y, outer.y);
  }
#else
  vec2 range = texelFetch(depthRangeTex, pixel, 0).xy;
  front = vec2(-range.x, range.y);
#endif
  return vec4(front, back);
}
