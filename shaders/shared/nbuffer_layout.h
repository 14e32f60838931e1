// Units of the N-buffer build (nbuffer_level0.comp, nbuffer_level.comp; C++:
// app/gl/nbuffer_build.cpp). Level 0 writes the coarser image from the layers; level n reads
// level n-1 as the finer image.
#define NBUFFER_NEAR_UNIT 0
#define NBUFFER_FAR_UNIT 1
#define NBUFFER_FINER_IMAGE 0
#define NBUFFER_COARSER_IMAGE 1
#define NBUFFER_LEVEL_LOCATION 0
