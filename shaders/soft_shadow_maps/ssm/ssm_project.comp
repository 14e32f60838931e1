// Soft shadow maps, step 6 (Atty et al. 2006 §3.1, Fig. 2(d)): the soft shadow map projected
// onto the scene from the light. visibility = 1 - accumulated occlusion, clamped to [0, 1]
// (overlapping micro-patches can sum past 1, §4.1.2; clamped pixels are counted). With two
// passes the occlusion is the larger of the two soft shadow maps (§3.5, Fig. 10(d)).
// Occluders are not receivers: SSM computes no self-shadowing (§1), so a point lying in front
// of the receiver map (an occluder's surface) is lit.
#include "shared/screen_pass.glsl"
#include "ssm_common.glsl"
layout(binding = SSM_PROJECT_WS_POSITION_UNIT) uniform sampler2D wsPositionTexture;
layout(binding = SSM_PROJECT_RECEIVER_UNIT) uniform sampler2D receiverMap;
layout(binding = SSM_PROJECT_SOFT_SHADOW_MAP_UNIT) uniform sampler2D softShadowMap;  // r: front, g: back
layout(binding = SSM_PROJECT_VISIBILITY_IMAGE, r32f) uniform writeonly image2D visibilityImage;
layout(std430, binding = SSM_COUNTERS_BINDING) buffer Counters { SsmCounters counters; };

void main() {
  ivec2 pixel = screenPixel();
  if (pixel.x < 0) return;
  vec4 wsPosition = texelFetch(wsPositionTexture, pixel, 0);
  vec3 map = lightMapCoords(wsPosition.xyz);
  bool insideMap = all(greaterThanEqual(map.xy, vec2(0.0))) && all(lessThan(map.xy, vec2(1.0)))
                   && map.z >= lightPlaneZ();
  float visibility = 1.0;
  if (wsPosition.w > 0.0 && insideMap) {
    int n = ssm.map.x;
    ivec2 texel = ivec2(map.xy * float(n));
    float lsReceiver = texelFetch(receiverMap, texel, 0).r;
    // Is this point the receiver the map saw through this texel? Off the texel's centre ray
    // it may differ from the stored depth by the receiver's slope: at most the largest
    // depth step to a neighbouring texel (receiver_tolerance of them). Farther in front it
    // is an occluder's surface.
    float zReceiver = lsDepthToZ(lsReceiver), step = 0.0;
    const ivec2 neighbours[4] = ivec2[](ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1));
    for (int i = 0; i < 4; ++i) {
      float lsNeighbour = texelFetch(receiverMap, clamp(texel + neighbours[i], ivec2(0), ivec2(n - 1)), 0).r;
      if (lsNeighbour < 1.0) step = max(step, abs(lsDepthToZ(lsNeighbour) - zReceiver));
    }
    float tolerance = ssm.tolerance.x * step + 1e-4 * zReceiver;
    if (lsReceiver < 1.0 && map.z >= zReceiver - tolerance) {
      vec2 occlusions = texelFetch(softShadowMap, texel, 0).rg;
      float occlusion = ssm.map.z == 2 ? max(occlusions.r, occlusions.g) : occlusions.r;
      if (occlusion > 1.0) atomicAdd(counters.clampedPixels, 1u);
      visibility = 1.0 - clamp(occlusion, 0.0, 1.0);
    } else {
      atomicAdd(counters.occluderPixels, 1u);
    }
  }
  imageStore(visibilityImage, pixel, vec4(visibility));
}
