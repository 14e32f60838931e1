// Light depth layers (thesis §3.3): the fragment's linear light depth (frame_block.h). The
// near layer is the depth attachment, so the depth test (LESS) keeps the nearest surface
// along each light ray; the far layer is a colour target blended with MAX (issue 14), so the
// farthest stays, in two targets: the layer, and a copy that light_layers_risers.frag reads
// while it changes the layer (a colour target, so that pass touches only sheet texels).
// Each pass writes both; the other's targets are not attached.
#define FRAME_BLOCKS_FROM_VERTEX_STAGE  // frame.glsl: why
#include "shared/frame.glsl"
#include "shared/light_layers_layout.h"
layout(location = 0) in vec3 wsPosition;
layout(location = LIGHT_LAYERS_FAR_LOCATION) out float farLayer;
layout(location = LIGHT_LAYERS_FAR_COPY_LOCATION) out float farCopy;
void main() {
  vec4 lsPosition = light.lightViewFromWorld * vec4(wsPosition, 1.0);
  float lsDepth = clamp(zToLsDepth(-lsPosition.z), 0.0, 1.0);
  gl_FragDepth = lsDepth;
  farLayer = lsDepth;
  farCopy = lsDepth;
}
