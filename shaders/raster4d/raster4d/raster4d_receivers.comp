// raster4d STEP 2 (Wang et al. 2020, Algorithm 1 lines 3-6): the output samples are the
// G-buffer's receivers, moved off their surface as the reference moves its ray origins;
// their light-space positions and the bounds of their Proj4 rectangles on P. The bounds
// are kept as (x -+ a)/d so that they do not depend on D, the depth of P, which is the
// farthest receiver's depth (P must lie behind every receiver, Appendix proof).
#include "raster4d.glsl"
#include "shared/reference_origin.h"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D wsPositionTexture;
layout(binding = 1) uniform sampler2D wsNormalTexture;
layout(std430, binding = R4D_RECEIVERS_RECEIVERS) writeonly buffer Receivers { vec4 receivers[]; };
layout(std430, binding = R4D_RECEIVERS_STATE) buffer State { Raster4dState state; };

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (pixel.x >= r4d.sizes.z || pixel.y >= r4d.sizes.w) return;
  uint index = uint(pixel.y * r4d.sizes.z + pixel.x);
  vec4 wsPosition = texelFetch(wsPositionTexture, pixel, 0);
  if (wsPosition.w <= 0.0) {  // background: nothing to shade
    receivers[index] = vec4(0.0);
    return;
  }
  vec3 wsNormal = texelFetch(wsNormalTexture, pixel, 0).xyz;
  // The reference's origin offset (reference_trace.h, "Origin"), computed the same way.
  vec3 size = abs(wsPosition.xyz);
  float offset = max(r4d.plane.z, float(REFERENCE_RELATIVE_OFFSET) * max(size.x, max(size.y, size.z)));
  vec3 lsReceiver = lightSpace(wsPosition.xyz + offset * wsNormal);
  if (lsReceiver.z <= r4d.plane.w) {  // at or behind the light plane: the light faces away
    receivers[index] = vec4(lsReceiver, 2.0);
    atomicAdd(state.counts.y, 1u);
    return;
  }
  receivers[index] = vec4(lsReceiver, 1.0);
  atomicAdd(state.counts.x, 1u);
  vec2 lo = (lsReceiver.xy - r4d.light.xy) / lsReceiver.z;
  vec2 hi = (lsReceiver.xy + r4d.light.xy) / lsReceiver.z;
  atomicMin(state.boundsMin.x, orderedFromFloat(lo.x));
  atomicMin(state.boundsMin.y, orderedFromFloat(lo.y));
  atomicMax(state.boundsMax.x, orderedFromFloat(hi.x));
  atomicMax(state.boundsMax.y, orderedFromFloat(hi.y));
  atomicMax(state.boundsMax.z, orderedFromFloat(lsReceiver.z));
}
