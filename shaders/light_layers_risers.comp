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
// Written for llvmpipe, where the pass is bound by its reads (issue 14): without a branch on
// the texel (llvmpipe runs both sides of a branch for all 8 lanes, so the neighbours' reads
// cost every texel anyway), and one invocation per 2 x 2 block of texels, which share their
// neighbours: the block reads the 4 x 4 texels around it once, by 4 gathers per layer, 8
// reads for 4 texels where one invocation per texel made 28 (5 near fetches and 2 far
// gathers each).
#include "shared/frame.glsl"
#include "shared/light_layers_layout.h"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = RISERS_NEAR_UNIT) uniform sampler2D nearLayer;
layout(binding = RISERS_FAR_UNIT) uniform sampler2D farLayer;  // as rasterized
layout(binding = RISERS_FAR_IMAGE, r32f) uniform writeonly image2D farImage;
layout(location = RISERS_CLOSE_LOCATION) uniform bool uCloseRisers;

const float kSheet = 1e-6, kMaxSlope = 6.0;

bool isSheet(float nearDepth, float farDepth) { return farDepth >= nearDepth && farDepth - nearDepth <= kSheet; }

// The far depth of one texel, from its near and far depths and those of its 4-neighbours
// n, f (left, below, above, right).
float closedFar(float nearDepth, float farDepth, vec4 n, vec4 f, int size) {
  // One texel's width in world units at this depth, in lsDepth units.
  float z = lsDepthToZ(farDepth);
  float texelWorld = 2.0 * z * max(light.lightDepthRange.z, light.lightDepthRange.w) / float(size);
  float cap = kMaxSlope * texelWorld / (light.lightDepthRange.y - light.lightDepthRange.x);
  // The deepest neighbour that is a sheet texel no more than `cap` deeper.
  float raised = farDepth;
  for (int k = 0; k < 4; ++k)
    if (isSheet(n[k], f[k]) && f[k] - farDepth <= cap) raised = max(raised, f[k]);
  bool close = uCloseRisers && isSheet(nearDepth, farDepth);
  return close ? raised : farDepth;
}

void main() {
  ivec2 size = textureSize(farLayer, 0), last = size - 1;
  ivec2 origin = RISERS_BLOCK * ivec2(gl_GlobalInvocationID.xy);  // the block's lower-left texel
  if (any(greaterThanEqual(origin, size))) return;
  // 1. The texels origin - 1 .. origin + RISERS_BLOCK of both layers (near[i][j]: column i,
  //    row j), each layer by gathers around the corners of the 2 x 2 texels they return;
  //    gather order (GLSL 4.50 §8.9.4): (i0, j1), (i1, j1), (i1, j0), (i0, j0). A texel past
  //    the map's border is clamped to the edge (gl_texture.cpp), as one texel's neighbour
  //    past the border was clamped to the texel itself: the same texel, which never raises
  //    far (its f is far itself).
  // The arrays are indexed by constants only once the loops are unrolled, so they live in
  // registers (llvmpipe indexes a private array by a variable lane by lane).
  const int span = RISERS_BLOCK + 2;
  float near[span][span], far[span][span];
  for (int j = 0; j < span; j += 2)
    for (int i = 0; i < span; i += 2) {
      vec2 corner = vec2(origin + ivec2(i, j)) / vec2(size);
      vec4 n = textureGather(nearLayer, corner), f = textureGather(farLayer, corner);
      near[i][j + 1] = n.x, near[i + 1][j + 1] = n.y, near[i + 1][j] = n.z, near[i][j] = n.w;
      far[i][j + 1] = f.x, far[i + 1][j + 1] = f.y, far[i + 1][j] = f.z, far[i][j] = f.w;
    }
  // 2. Each texel of the block that lies in the map, from its own and its neighbours' depths.
  for (int j = 1; j <= RISERS_BLOCK; ++j)
    for (int i = 1; i <= RISERS_BLOCK; ++i) {
      ivec2 texel = origin + ivec2(i - 1, j - 1);
      if (any(greaterThan(texel, last))) continue;
      vec4 n = vec4(near[i - 1][j], near[i][j - 1], near[i][j + 1], near[i + 1][j]);
      vec4 f = vec4(far[i - 1][j], far[i][j - 1], far[i][j + 1], far[i + 1][j]);
      imageStore(farImage, texel, vec4(closedFar(near[i][j], far[i][j], n, f, size.x)));
    }
}
