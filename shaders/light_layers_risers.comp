// Stage `light_layers`, last step (issue 12): the far layer of a zero-thickness sheet
// reaches down to its neighbours' depths. A tilted sheet stored at texel centres is a
// staircase with near == far on every step; a ray that crosses the sheet between two steps'
// depths at their common edge met neither step and passed through (1-4% of the rays, +0.011
// mean visibility where the exact value is below 0.1, on a sheet tilted 35 degrees). Here a
// sheet texel (far - near below kSheet) takes as far the largest depth of its 4-neighbours
// that are sheet texels too and lie at most kMaxSlope texel widths deeper (the same sheet,
// tilted up to ~80 degrees, not another occluder), which closes every riser: the shallower
// step of each pair now spans the gap. Texels of closed or thick occluders (far > near)
// are copied unchanged.
#include "shared/frame.glsl"
#include "shared/light_layers_layout.h"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = RISERS_NEAR_UNIT) uniform sampler2D nearLayer;
layout(binding = RISERS_FAR_UNIT) uniform sampler2D farLayer;  // as rasterized
layout(binding = RISERS_FAR_IMAGE, r32f) uniform writeonly image2D farImage;
layout(location = RISERS_CLOSE_LOCATION) uniform bool uCloseRisers;

const float kSheet = 1e-6, kMaxSlope = 6.0;

bool isSheet(float nearDepth, float farDepth) { return farDepth >= nearDepth && farDepth - nearDepth <= kSheet; }

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy), size = textureSize(farLayer, 0);
  if (any(greaterThanEqual(texel, size))) return;
  float nearDepth = texelFetch(nearLayer, texel, 0).r, farDepth = texelFetch(farLayer, texel, 0).r;
  float result = farDepth;
  if (uCloseRisers && isSheet(nearDepth, farDepth)) {
    // One texel's width in world units at this depth, in lsDepth units.
    float z = lsDepthToZ(farDepth);
    float texelWorld = 2.0 * z * max(light.lightDepthRange.z, light.lightDepthRange.w) / float(size.x);
    float cap = kMaxSlope * texelWorld / (light.lightDepthRange.y - light.lightDepthRange.x);
    const ivec2 kSteps[4] = ivec2[4](ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1));
    for (int k = 0; k < 4; ++k) {
      ivec2 at = texel + kSteps[k];
      if (any(lessThan(at, ivec2(0))) || any(greaterThanEqual(at, size))) continue;
      float n = texelFetch(nearLayer, at, 0).r, f = texelFetch(farLayer, at, 0).r;
      if (isSheet(n, f) && f > result && f - farDepth <= cap) result = f;
    }
  }
  imageStore(farImage, texel, vec4(result));
}
