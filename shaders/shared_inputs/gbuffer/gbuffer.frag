// G-buffer (thesis Algorithm 1, step 1): the unshadowed scene from the eye.
#include "shared/frame.glsl"
#include "stages/shared_inputs/gbuffer/gbuffer_layout.h"
layout(location = 0) in vec3 wsPosition;
layout(location = 1) in vec3 wsNormal;
layout(location = GBUFFER_BASE_COLOR_LOCATION) uniform vec3 uBaseColor;
layout(location = GBUFFER_ALBEDO_ATTACHMENT) out vec4 outAlbedo;
layout(location = GBUFFER_NORMAL_ATTACHMENT) out vec4 outNormal;
layout(location = GBUFFER_POSITION_ATTACHMENT) out vec4 outPosition;
void main() {
  // Two-sided: a sheet seen from behind shades with its normal turned to the eye.
  vec3 n = normalize(wsNormal);
  if (!gl_FrontFacing) n = -n;
  outAlbedo = vec4(uBaseColor, 1.0);
  outNormal = vec4(n, 1.0);
  outPosition = vec4(wsPosition, 1.0);
}
