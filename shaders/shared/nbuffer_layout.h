// Units of the N-buffer build (nbuffer_levels01.frag, nbuffer_level.frag; C++:
// app/gl/nbuffer_build.cpp). Levels 0 and 1 read the layers and are fragment outputs 0 and
// 1; level n >= 2 reads level n-1 as the finer image and writes its level as output 0.
#define NBUFFER_NEAR_UNIT 0
#define NBUFFER_FAR_UNIT 1
#define NBUFFER_FINER_IMAGE 0
#define NBUFFER_LEVEL_LOCATION 0
