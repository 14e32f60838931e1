// Stage `hard_shadow`: the classic shadow-map test (Williams 1978; thesis §2.3) against the
// near layer. The map is seen from the projection point behind the light center, which
// tends to the center as the light shrinks (Eq 3.1), so this is the point-light limit.
#include "shared/screen_pass.glsl"
#include "shared/bias.glsl"
#include "stages/baselines/hard_shadow/hard_shadow_layout.h"
layout(binding = HARD_SHADOW_WS_POSITION_UNIT) uniform sampler2D wsPositionImage;
layout(binding = HARD_SHADOW_NEAR_UNIT) uniform sampler2D nearLayer;
layout(binding = HARD_SHADOW_WS_NORMAL_UNIT) uniform sampler2D wsNormalImage;
layout(binding = HARD_SHADOW_VISIBILITY_IMAGE, r32f) uniform writeonly image2D visibilityImage;
layout(location = HARD_SHADOW_OFFSET_LOCATION) uniform float uOffset;  // hard_shadow.offset: extra constant bias (world)

void main() {
  ivec2 pixel = screenPixel();
  if (pixel.x < 0) return;
  vec4 wsPosition = texelFetch(wsPositionImage, pixel, 0);
  float visibility = 1.0;
  vec3 map = lightMapCoords(wsPosition.xyz);
  bool insideMap = all(greaterThanEqual(map.xy, vec2(0.0))) && all(lessThan(map.xy, vec2(1.0)))
                   && map.z >= light.lightDepthRange.x;
  if (wsPosition.w > 0.0 && insideMap) {
    ivec2 texel = ivec2(map.xy * vec2(light.mapSize.xy));
    float nearDepth = texelFetch(nearLayer, texel, 0).r;
    float bias = light.bias.x + uOffset;
    if (light.bias.y != 0.0) {
      vec3 wsNormal = texelFetch(wsNormalImage, pixel, 0).xyz;
      bias += adaptiveBias(map.z, wsNormal, -light.wsLightForward.xyz, light.bias.z);
    }
    visibility = zToLsDepth(map.z - bias) <= nearDepth ? 1.0 : 0.0;
  }
  imageStore(visibilityImage, pixel, vec4(visibility));
}
