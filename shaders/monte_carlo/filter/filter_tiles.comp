// Stage `filter`, step 1: list the 8 x 8 tiles where the blur can change a value.
// The filter's output at a pixel is sum(w_k v_k) / sum(w_k) over the receivers in its
// (2r+1)^2 window (both passes), with the center's weight > 0; when every one of those v_k
// is exactly 0, the sum is 0, and when every one is exactly 1, the two sums add the same
// numbers in the same order, so the quotient is exactly 1: the pixel keeps its value. A
// tile is listed unless every pixel of the tile grown by r holds the same value, 0 or 1.
// Background pixels are never taps, but they are looked at too: one fetch per pixel
// instead of two, at the price of listing a tile where the background meets umbra.
// One 8 x 8 workgroup per tile (screen_pass.glsl): its invocations read the grown tile
// together, each every 8th pixel per axis, and gather what they saw in shared memory.
#include "shared/screen_pass.glsl"
#include "stages/monte_carlo/filter/filter_layout.h"
layout(binding = FILTER_SOURCE_UNIT) uniform sampler2D sourceImage;
layout(location = FILTER_RADIUS_LOCATION) uniform int uRadius;
layout(std430, binding = FILTER_TILES_BINDING) buffer FilterTiles {
  FilterTilesHeader header;
  uint tiles[];
};
shared uint groupSeen;

void main() {
  // 1. This group's tile (the group may reach past the image's last rows and columns).
  ivec2 size = ivec2(frame.sizes.xy);
  ivec2 tileOrigin = ivec2(gl_WorkGroupID.xy) * FILTER_TILE_SIZE + ivec2(0, uRowOffset);
  if (gl_LocalInvocationIndex == 0u) groupSeen = 0u;
  memoryBarrierShared();
  barrier();
  // 2. The values over the tile grown by the radius, clipped to the image: bit 0 a value 0,
  //    bit 1 a 1, bit 2 any other.
  ivec2 low = max(tileOrigin - uRadius, ivec2(0));
  ivec2 high = min(tileOrigin + FILTER_TILE_SIZE + uRadius, size);
  uint seen = 0u;
  for (int y = low.y + int(gl_LocalInvocationID.y); y < high.y; y += FILTER_TILE_SIZE)
    for (int x = low.x + int(gl_LocalInvocationID.x); x < high.x; x += FILTER_TILE_SIZE) {
      uint value = floatBitsToUint(texelFetch(sourceImage, ivec2(x, y), 0).r);
      seen |= value == 0u ? 1u : value == floatBitsToUint(1.0) ? 2u : 4u;  // -0.0 is "other"
    }
  if (seen != 0u) atomicOr(groupSeen, seen);
  memoryBarrierShared();
  barrier();
  // 3. Listed when more than one value, or a value other than 0 and 1, was seen.
  if (gl_LocalInvocationIndex != 0u || groupSeen < 3u) return;
  ivec2 tile = tileOrigin / FILTER_TILE_SIZE;
  uint slot = atomicAdd(header.groups[0], 1u);
  tiles[slot] = uint(tile.x) | (uint(tile.y) << 16);
  ivec2 inside = min(size - tileOrigin, ivec2(FILTER_TILE_SIZE));
  atomicAdd(header.pixels, uint(inside.x * inside.y));
}
