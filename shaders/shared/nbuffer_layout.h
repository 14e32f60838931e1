// Units of the N-buffer build (nbuffer_level0.frag, nbuffer_level.frag; C++:
// app/gl/nbuffer_build.cpp). Level 0 reads the layers; level n reads level n-1 as the finer
// image; both write their level as fragment output 0.
#define NBUFFER_NEAR_UNIT 0
#define NBUFFER_FAR_UNIT 1
#define NBUFFER_FINER_IMAGE 0
#define NBUFFER_LEVEL_LOCATION 0
