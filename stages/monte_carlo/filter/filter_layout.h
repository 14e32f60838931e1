// Units and locations of filter.comp and filter_tiles.comp (C++:
// stages/monte_carlo/filter/filter.cpp): the inputs are read with texelFetch, the target written as
// an image.
#define FILTER_TARGET_IMAGE 0        // written
#define FILTER_SOURCE_UNIT 0
#define FILTER_WS_POSITION_UNIT 1
#define FILTER_WS_NORMAL_UNIT 2
#define FILTER_ZRANGE_UNIT 3
#define FILTER_DIRECTION_LOCATION 1  // after ROW_OFFSET_LOCATION
#define FILTER_RADIUS_LOCATION 2
#define FILTER_DEPTH_SCALE_LOCATION 3
#define FILTER_NORMAL_POWER_LOCATION 4
#define FILTER_TILED_LOCATION 5
#define FILTER_PLANE_SIGMA_LOCATION 6
#define FILTER_PIXEL_ANGLE_LOCATION 7
#define FILTER_PENUMBRA_SCALE_LOCATION 8

// The tiles the filter runs on (filter_tiles.comp writes it, filter.comp reads
// it): a std430 storage buffer holding a glDispatchComputeIndirect command (groups x, y, z:
// one 8 x 8 group per tile), the number of image pixels in the listed tiles, then
// uint tiles[] packed x | y << 16 in tile units. Frame buffer name "filter.tiles".
#define FILTER_TILES_BINDING 0
#define FILTER_TILE_SIZE 8  // = the 8 x 8 groups of screen_pass.glsl
// The largest radius (filter.radius's maximum): filter.comp's shared rows hold the tile's 8
// pixels plus this many taps at either end.
#define FILTER_MAX_RADIUS 32
struct FilterTilesHeader {
  uint groups[3];
  uint pixels;
};
