// Units of the min-max mipmap build (minmax_level.frag; C++: app/gl/minmax_build.cpp).
// Level 0 reads the layers; level n >= 1 reads level n-1 of the same atlas image.
#define MINMAX_NEAR_UNIT 0
#define MINMAX_FAR_UNIT 1
#define MINMAX_ATLAS_IMAGE 0
#define MINMAX_LEVEL_LOCATION 0   // the level written, n >= 0
#define MINMAX_SIZE_LOCATION 1    // level-0 size W, H
