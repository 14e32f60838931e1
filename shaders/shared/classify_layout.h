// Layout of stage `classify`'s pixel counts, read by C++ (stages/monte_carlo/classify.cpp, checked with
// static_assert) and GLSL: a std430 storage buffer at CLASSIFY_COUNTS_BINDING holding one
// uint per class of classes.h (std430 uint arrays have stride 4, as in C++).
// Units and locations of classify.frag and classify_list.comp (C++:
// stages/monte_carlo/classify.cpp). What can be is read through image units, not texture
// units: on llvmpipe an imageLoad costs a third of a texelFetch (bench/llvmpipe-reads); the
// near layer is a depth texture, which no image format reads.
#define CLASSIFY_WS_POSITION_IMAGE 0
#define CLASSIFY_WS_NORMAL_IMAGE 1
#define CLASSIFY_LEVELS_IMAGE 2     // the N-buffer (image2DArray)
#define CLASSIFY_MINMAX_IMAGE 3     // or the min-max mipmap's atlas (image2D, minmax.glsl),
#define CLASSIFY_NEAR_UNIT 0        // whose level 0 is the near (sampler2D)
#define CLASSIFY_FAR_IMAGE 4        // and far layers
#define CLASSIFY_MASK_IMAGE 0       // classify_list.comp: the mask classify.frag wrote
#define CLASSIFY_ITERATIONS_LOCATION 1
#define CLASSIFY_UMBRA_TEST_LOCATION 2
#define CLASSIFY_MINMAX_CELLS_LOCATION 3  // int: cells per axis over the min-max mipmap
                                          // (classify.minmax_cells; its program only)

#define CLASSIFY_COUNTS_BINDING 2
#define CLASSIFY_CLASS_COUNT 5
struct ClassifyCounts {
  uint pixels[8];  // indexed by CLASS_*; 5..7 unused (padding to 32 bytes)
};

// The pixels that still need rays (penumbra and umbra): a std430 buffer of uint count, 3
// uints of padding, then uint pixels[] packed x | y << 16; written by classify, read by
// trace, so the trace pass runs over them alone (thesis Fig 3.8: "full calculations are
// only performed in blue areas"). Frame buffer name "classify.tracedPixels".
#define CLASSIFY_LIST_BINDING 3
#define CLASSIFY_LIST_TILE 8  // classify_list.comp: pixels per axis of one invocation's tile
#define CLASSIFY_LIST_HEADER_BYTES 16
