// Units of the min-max mipmap build (minmax_level.frag; C++: stages/shared_inputs/minmax/minmax_build.cpp).
// Level 1 reads the layers; level n >= 2 reads level n-1 through a view of its mip level.
#define MINMAX_NEAR_UNIT 0
#define MINMAX_FAR_UNIT 1
#define MINMAX_FINER_UNIT 2        // level n-1 (a view of mip level n-2), n >= 2
#define MINMAX_LEVEL_LOCATION 0   // the level written, n >= 1
#define MINMAX_SIZE_LOCATION 1    // level-0 size W, H
