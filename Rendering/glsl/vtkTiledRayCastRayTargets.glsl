//============================================================================
// TiledRayCast, fragment pipeline: each pixel's ray state (tet, lambda,
// status, entry face), colour and last entry, kept in two ping-pong triples
// of render targets. A pass reads one triple (in_state, in_color, in_entry:
// the traversal and the copy) and writes the other (fragOutput0 to 2: every
// pass that starts or moves rays). The three always flip together.
//
// The compute pipeline has no such targets: where a raster pass writes an
// entry here, it appends it to the pixel's entry list instead
// (vtkTiledRayCastEntryList.glsl).
//============================================================================
uniform sampler2D in_state;
uniform sampler2D in_color;
uniform sampler2D in_entry;

layout(location = 0) out vec4 fragOutput0;
layout(location = 1) out vec4 fragOutput1;
layout(location = 2) out vec4 fragOutput2;
