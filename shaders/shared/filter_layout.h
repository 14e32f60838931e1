// Image units and locations of filter.comp and filter_tiles.comp (C++:
// stages/monte_carlo/filter.cpp). Read through image units, not texture units: on llvmpipe
// an imageLoad costs a third of a texelFetch (bench/llvmpipe-reads).
#define FILTER_TARGET_IMAGE 0        // written
#define FILTER_SOURCE_IMAGE 1
#define FILTER_WS_POSITION_IMAGE 2
#define FILTER_WS_NORMAL_IMAGE 3
#define FILTER_ZRANGE_IMAGE 4
#define FILTER_DIRECTION_LOCATION 1  // after ROW_OFFSET_LOCATION
#define FILTER_RADIUS_LOCATION 2
#define FILTER_DEPTH_SCALE_LOCATION 3
#define FILTER_NORMAL_POWER_LOCATION 4
#define FILTER_TILED_LOCATION 5
#define FILTER_PLANE_SIGMA_LOCATION 6
#define FILTER_PIXEL_ANGLE_LOCATION 7
#define FILTER_PENUMBRA_SCALE_LOCATION 8

// The tiles the filter runs on (issue 14; filter_tiles.comp writes it, filter.comp reads
// it): a std430 storage buffer holding a glDispatchComputeIndirect command (groups x, y, z:
// one 8 x 8 group per tile), the number of image pixels in the listed tiles, then
// uint tiles[] packed x | y << 16 in tile units. Frame buffer name "filter.tiles".
#define FILTER_TILES_BINDING 0
#define FILTER_TILE_SIZE 8  // = the 8 x 8 groups of screen_pass.glsl
// Pixels one invocation filters, consecutive along the pass's direction, sharing their taps
// (filter.comp); a tile's group has FILTER_TILE_SIZE^2 / 4 invocations.
#define FILTER_PIXELS_PER_INVOCATION 4
struct FilterTilesHeader {
  uint groups[3];
  uint pixels;
};
