// What every soft-shadow-map pass reads: the light (frame.glsl), the micro-patch geometry
// (ssm_patch.glsl) and the stage's parameters (ssm_layout.h).
#include "shared/frame.glsl"
#include "shared/ssm_patch.glsl"
#include "shared/ssm_layout.h"
layout(std140, binding = SSM_PARAMS_BINDING) uniform SsmBlock { SsmParams ssm; };

float lightPlaneZ() { return light.lightDepthRange.x; }  // Eq 3.1: the light depth
vec2 lightHalfSize() { return vec2(light.wsLightRight.w, light.wsLightUp.w); }
vec2 tanHalfFov() { return light.lightDepthRange.zw; }

// The point of the ray through the centre of map texel `texel` at view depth z.
vec3 lsPointOfTexel(ivec2 texel, float z) {
  vec2 ndc = (vec2(texel) + 0.5) / float(ssm.map.x) * 2.0 - 1.0;
  return vec3(ndc * tanHalfFov() * z, z);
}
