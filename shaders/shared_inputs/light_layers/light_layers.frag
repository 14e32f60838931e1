// Light depth layers (thesis §3.3): the fragment's linear light depth (frame_block.h) is
// written as its depth, so the depth test picks the nearest (near layer, LESS) or the
// farthest (far layer, GREATER) surface along each light ray. In the far pass the fragments
// that pass the test write it as colour too (the far layer's target), so the
// colour target ends with the farthest depth as the depth buffer does, and beside it the
// slope of their plane: 1 / z per texel along x and y. 1 / z is affine in the map's texel
// coordinates over a planar triangle (a perspective projection), so these two numbers give
// the depth the same plane has at any neighbouring texel's centre exactly; the risers pass
// (light_layers_risers.frag) uses them to tell a neighbour on the same sheet from another
// occluder.
#include "shared/frame.glsl"
#include "stages/shared_inputs/light_layers/light_layers_layout.h"
layout(location = 0) in vec3 wsPosition;
layout(location = LIGHT_LAYERS_FAR_LOCATION) out float farLayer;
layout(location = LIGHT_LAYERS_SLOPE_LOCATION) out vec2 farSlope;
void main() {
  vec4 lsPosition = light.lightViewFromWorld * vec4(wsPosition, 1.0);
  float lsDepth = clamp(zToLsDepth(-lsPosition.z), 0.0, 1.0);
  gl_FragDepth = lsDepth;
  farLayer = lsDepth;
  float invZ = 1.0 / -lsPosition.z;
  farSlope = vec2(dFdx(invZ), dFdy(invZ));
}
