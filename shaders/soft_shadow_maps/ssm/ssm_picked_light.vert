// Soft shadow maps, the picked receiver's view (Atty et al. 2006 §3.4, §4.1.2, Fig. 12): every
// micro-patch back-projected from that receiver onto the light, drawn in light coordinates
// ([0,1]^2 fills the view). Counted with additive blending: 0 is light seen through a gap
// (a light leak), 1 hidden once, 2 or more an overlap (over-darkening, bounded by Eq 3).
#include "ssm_common.glsl"
layout(binding = SSM_PICKED_OCCLUDER_UNIT) uniform sampler2D occluderMap;
layout(binding = SSM_PICKED_RECEIVER_UNIT) uniform sampler2D receiverMap;
layout(binding = SSM_PICKED_WS_POSITION_UNIT) uniform sampler2D wsPositionTexture;

void main() {
  int n = ssm.map.x;
  ivec2 texel = ivec2(gl_InstanceID % n, gl_InstanceID / n);
  float lsDepth = texelFetch(occluderMap, texel, 0).r;
  vec3 map = lightMapCoords(texelFetch(wsPositionTexture, ssm.pick.xy, 0).xyz);
  ivec2 receiverTexel = ivec2(clamp(map.xy, 0.0, 0.999999) * float(n));
  float lsReceiver = texelFetch(receiverMap, receiverTexel, 0).r;
  bool empty = ssm.map.y == 0 ? lsDepth >= 1.0 : lsDepth <= 0.0;
  float z = lsDepthToZ(lsDepth), zReceiver = lsDepthToZ(lsReceiver);
  if (empty || lsDepth <= 0.0 || lsReceiver >= 1.0 || zReceiver <= z) {
    gl_Position = vec4(-2.0, -2.0, 0.0, 1.0);
    return;
  }
  // The receiver the soft shadow map used for this pixel: its texel's centre ray.
  vec3 lsPoint = lsPointOfTexel(receiverTexel, zReceiver);
  MicroPatch micro = microPatchOfTexel(texel, vec2(n), z, tanHalfFov());
  float scale = (zReceiver - lightPlaneZ()) / (zReceiver - z);  // as in microPatchOcclusion
  vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);
  vec2 onPatch = mix(micro.lsMin, micro.lsMax, corner);
  vec2 onLight = lsPoint.xy + (onPatch - lsPoint.xy) * scale;
  gl_Position = vec4(onLight / lightHalfSize(), 0.0, 1.0);  // light rectangle -> [-1,1]^2
}
