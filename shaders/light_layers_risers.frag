// Stage `light_layers`, last step: the far layer of a zero-thickness sheet
// reaches down to its neighbours' depths. A tilted sheet stored at texel centres is a
// staircase with near == far on every step; a ray that crosses the sheet between two steps'
// depths at their common edge met neither step and passed through (1-4% of the rays, +0.011
// mean visibility where the exact value is below 0.1, on a sheet tilted 35 degrees). Here a
// sheet texel (far - near below kSheet) takes as far the largest depth of its 4-neighbours
// that are sheet texels too and lie at most kMaxSlope texel widths deeper (the same sheet,
// tilted up to ~80 degrees, not another occluder), which closes every riser: the shallower
// step of each pair now spans the gap. Texels of closed or thick occluders (far > near), and
// texels with no occluder, keep what the far pass wrote.
// A fragment shader over the rectangle of the map the occluders can cover
// (app/gl/screen_triangle.h), discarding every texel but a sheet's: a discarded fragment
// writes nothing, so every other texel keeps what the far pass wrote without a copy.
#include "shared/frame.glsl"
#include "shared/light_layers_layout.h"
layout(binding = RISERS_NEAR_UNIT) uniform sampler2D nearLayer;
layout(binding = RISERS_FAR_UNIT) uniform sampler2D farRasterized;  // the far pass's depth buffer
layout(location = RISERS_CLOSE_LOCATION) uniform bool uCloseRisers;
layout(location = 0) out float farOut;

const float kSheet = 1e-6, kMaxSlope = 6.0;

bool isSheet(float nearDepth, float farDepth) {
  return farDepth >= nearDepth && farDepth - nearDepth <= kSheet;
}

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy), last = textureSize(farRasterized, 0) - 1;
  float nearDepth = texelFetch(nearLayer, texel, 0).r;
  float farDepth = texelFetch(farRasterized, texel, 0).r;
  if (!uCloseRisers || !isSheet(nearDepth, farDepth)) discard;
  // One texel's width in world units at this depth, in lsDepth units.
  float z = lsDepthToZ(farDepth);
  float tanHalfFov = max(light.lightDepthRange.z, light.lightDepthRange.w);
  float texelWorld = 2.0 * z * tanHalfFov / float(last.x + 1);
  float cap = kMaxSlope * texelWorld / (light.lightDepthRange.y - light.lightDepthRange.x);
  // The deepest neighbour (left, below, above, right) that is a sheet texel no more than
  // `cap` deeper. A neighbour past the map's border is the texel itself, which never raises
  // far (its far is far itself).
  const ivec2 offsets[4] = ivec2[4](ivec2(-1, 0), ivec2(0, -1), ivec2(0, 1), ivec2(1, 0));
  float raised = farDepth;
  for (int k = 0; k < 4; ++k) {
    ivec2 neighbour = clamp(texel + offsets[k], ivec2(0), last);
    float n = texelFetch(nearLayer, neighbour, 0).r, f = texelFetch(farRasterized, neighbour, 0).r;
    if (isSheet(n, f) && f - farDepth <= cap) raised = max(raised, f);
  }
  farOut = raised;
}
