// Soft shadow maps, step 5 (Atty et al. 2006 §3.4, Fig. 9): for the receiver seen through
// this soft-shadow-map texel, the fraction of the light the micro-patch hides; additive
// blending sums the micro-patches (the colour mask picks this pass's channel).
#include "ssm_common.glsl"
layout(binding = SSM_PATCHES_RECEIVER_UNIT) uniform sampler2D receiverMap;
layout(location = 0) flat in vec4 vPatchRect;
layout(location = 1) flat in float vPatchZ;
layout(location = 0) out vec2 outOcclusion;
layout(location = 1) out float outCount;  // micro-patches that hid some of the light here

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  float lsReceiver = texelFetch(receiverMap, texel, 0).r;
  if (lsReceiver >= 1.0) discard;  // no receiver seen through this texel
  vec3 lsPoint = lsPointOfTexel(texel, lsDepthToZ(lsReceiver));
  float occlusion = microPatchOcclusion(MicroPatch(vPatchRect.xy, vPatchRect.zw, vPatchZ),
                                        lsPoint, lightHalfSize(), lightPlaneZ());
  if (ssm.map.w != 0) {  // the picked texel's footprint: occlusion, and 1 over the whole quad
    outOcclusion = vec2(occlusion, 1.0);
    return;
  }
  if (occlusion <= 0.0) discard;
  outOcclusion = vec2(occlusion);
  outCount = 1.0;
}
