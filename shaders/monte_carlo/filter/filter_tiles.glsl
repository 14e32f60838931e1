// The tile of a filter group: with uTiled, the tile its group was given
// (filter_tiles.comp listed it); otherwise the groups cover the image in row bands
// (dispatchRows: one group per 8 x 8 pixels, the band's first row in uRowOffset).
#include "stages/monte_carlo/filter/filter_layout.h"
#include "shared/screen_pass_layout.h"
#if FILTER_TILE_SIZE != 8
#error "a filter tile is the 8 x 8 pixels of one dispatchRows group"
#endif
layout(std430, binding = FILTER_TILES_BINDING) readonly buffer FilterTiles {
  FilterTilesHeader header;
  uint tiles[];
};
layout(location = FILTER_TILED_LOCATION) uniform int uTiled;
layout(location = ROW_OFFSET_LOCATION) uniform int uRowOffset;

// The tile's lower-left pixel.
ivec2 filteredTile() {
  if (uTiled == 0) return ivec2(gl_WorkGroupID.xy) * FILTER_TILE_SIZE + ivec2(0, uRowOffset);
  uint tile = tiles[gl_WorkGroupID.x];
  return ivec2(int(tile & 0xFFFFu), int(tile >> 16)) * FILTER_TILE_SIZE;
}
