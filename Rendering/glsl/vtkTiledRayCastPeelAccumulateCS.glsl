#version 430 core
//============================================================================
// TiledRayCast, compute pipeline: one set of volumes' part of a stage of VTK's
// dual depth peeling (a group traversed together, or a volume alone), added to
// the stage's accumulation (vtkTiledRayCastPeelAccumulation). The sets are
// drawn farthest first, so each set's front and back colours go over what the
// sets behind it left, premultiplied (C = c + (1 - a) C); the stage's first
// set stores its own.
//============================================================================
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 4, rgba16) uniform readonly image2D in_setColor;
layout(binding = 5, rgba16) uniform readonly image2D in_setBackColor;
layout(binding = 6, rgba16) uniform image2D in_accumulatedColor;
layout(binding = 7, rgba16) uniform image2D in_accumulatedBackColor;
uniform ivec2 in_size;
uniform int in_over; // 0: the stage's first set

void main()
{
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, in_size)))
  {
    return;
  }
  vec4 front = imageLoad(in_setColor, pixel);
  vec4 back = imageLoad(in_setBackColor, pixel);
  if (in_over != 0)
  {
    front += (1.0 - front.a) * imageLoad(in_accumulatedColor, pixel);
    back += (1.0 - back.a) * imageLoad(in_accumulatedBackColor, pixel);
  }
  imageStore(in_accumulatedColor, pixel, front);
  imageStore(in_accumulatedBackColor, pixel, back);
}
