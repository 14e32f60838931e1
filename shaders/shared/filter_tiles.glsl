// The pixel of a filter invocation (issue 14): with uTiled, the invocation's pixel in the
// tile its group was given (filter_tiles.comp listed it); otherwise every pixel in rows.
#include "filter_layout.h"
#if FILTER_TILE_SIZE != 8
#error "a filter tile is one 8 x 8 group of screen_pass.glsl"
#endif
layout(std430, binding = FILTER_TILES_BINDING) readonly buffer FilterTiles {
  FilterTilesHeader header;
  uint tiles[];
};
layout(location = FILTER_TILED_LOCATION) uniform int uTiled;

ivec2 filteredPixel() {
  if (uTiled == 0) return screenPixel();
  uint tile = tiles[gl_WorkGroupID.x];
  ivec2 pixel = ivec2(int(tile & 0xFFFFu), int(tile >> 16)) * FILTER_TILE_SIZE +
                ivec2(gl_LocalInvocationID.xy);
  return all(lessThan(pixel, ivec2(frame.sizes.xy))) ? pixel : ivec2(-1);
}
