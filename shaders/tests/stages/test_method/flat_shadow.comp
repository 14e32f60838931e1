// Stage `flat_shadow` (tests only; docs/design.md#add-a-method): the smallest shadow method
// there is, to show that one folder and one registry line make a method. It shades no
// occluder: every receiver point sees the fraction `level` of the light, and pixels with no
// surface (w = 0 in the G-buffer) see all of it. One pixel per invocation.
#include "../../../shared/screen_pass.glsl"
#include "tests/stages/test_method/flat_shadow_layout.h"
layout(binding = FLAT_SHADOW_WS_POSITION_UNIT) uniform sampler2D wsPositionImage;
layout(binding = FLAT_SHADOW_VISIBILITY_IMAGE, r32f) uniform writeonly image2D visibilityImage;
layout(location = FLAT_SHADOW_LEVEL_LOCATION) uniform float uLevel;  // flat_shadow.level

void main() {
  ivec2 pixel = screenPixel();
  if (pixel.x < 0) return;
  vec4 wsPosition = texelFetch(wsPositionImage, pixel, 0);
  float visibility = wsPosition.w > 0.0 ? uLevel : 1.0;
  imageStore(visibilityImage, pixel, vec4(visibility));
}
