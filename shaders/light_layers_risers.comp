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
// Written without a branch on the texel: llvmpipe runs both sides of a branch for all 8
// lanes, so the neighbours' reads cost every texel anyway (issue 14: at a 2048^2 map the
// pass took 60 of the stage's 70 ms); here a texel reads 5 near texels (itself and its
// 4-neighbours) by texelFetch and the far ones by 2 gathers.
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
  // 1. The texel and its 4-neighbours (left, below, above, right). A neighbour past the
  //    map's border is clamped to the texel itself (the textures clamp to the edge,
  //    gl_texture.cpp), which never raises far (its f is far itself).
  //    The far layer in two gathers, around the texel's lower-left corner (texels x-1..x,
  //    y-1..y) and its upper-right corner (x..x+1, y..y+1); gather order (GLSL 4.50
  //    §8.9.4): (i0, j1), (i1, j1), (i1, j0), (i0, j0). The near layer by texelFetch:
  //    gathering it too changed later classification in one case on llvmpipe (not
  //    understood; bench/llvmpipe-branches/README.md).
  vec4 farLowerLeft = textureGather(farLayer, vec2(texel) / vec2(size));
  vec4 farUpperRight = textureGather(farLayer, vec2(texel + 1) / vec2(size));
  float farDepth = farLowerLeft.y, nearDepth = texelFetch(nearLayer, texel, 0).r;
  vec4 f = vec4(farLowerLeft.x, farLowerLeft.z, farUpperRight.x, farUpperRight.z);
  ivec2 last = size - 1;
  vec4 n = vec4(texelFetch(nearLayer, max(texel - ivec2(1, 0), 0), 0).r,
                texelFetch(nearLayer, max(texel - ivec2(0, 1), 0), 0).r,
                texelFetch(nearLayer, min(texel + ivec2(0, 1), last), 0).r,
                texelFetch(nearLayer, min(texel + ivec2(1, 0), last), 0).r);
  // 2. One texel's width in world units at this depth, in lsDepth units.
  float z = lsDepthToZ(farDepth);
  float texelWorld =
      2.0 * z * max(light.lightDepthRange.z, light.lightDepthRange.w) / float(size.x);
  float cap = kMaxSlope * texelWorld / (light.lightDepthRange.y - light.lightDepthRange.x);
  // 3. The deepest neighbour that is a sheet texel no more than `cap` deeper.
  float raised = farDepth;
  for (int k = 0; k < 4; ++k)
    if (isSheet(n[k], f[k]) && f[k] - farDepth <= cap) raised = max(raised, f[k]);
  bool close = uCloseRisers && isSheet(nearDepth, farDepth);
  imageStore(farImage, texel, vec4(close ? raised : farDepth));
}
