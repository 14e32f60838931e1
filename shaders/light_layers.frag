// Light depth layers (thesis §3.3): the fragment's linear light depth (frame_block.h) is
// written as its depth, so the depth test picks the nearest (near layer, LESS) or the
// farthest (far layer, GREATER) surface along each light ray. In the far pass the fragments
// that pass the test write it as colour too (the far layer's target), so the
// colour target ends with the farthest depth as the depth buffer does.
#include "shared/frame.glsl"
#include "shared/light_layers_layout.h"
layout(location = 0) in vec3 wsPosition;
layout(location = LIGHT_LAYERS_FAR_LOCATION) out float farLayer;
void main() {
  vec4 lsPosition = light.lightViewFromWorld * vec4(wsPosition, 1.0);
  float lsDepth = clamp(zToLsDepth(-lsPosition.z), 0.0, 1.0);
  gl_FragDepth = lsDepth;
  farLayer = lsDepth;
}
