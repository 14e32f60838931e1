// Layout of stage `classify`'s pixel counts, read by C++ (stages/monte_carlo/classify/classify.cpp, checked with
// static_assert) and GLSL: a std430 storage buffer at CLASSIFY_COUNTS_BINDING holding one
// uint per class of classes.h (std430 uint arrays have stride 4, as in C++).
// Texture units (all read with texelFetch) and locations of classify.frag and
// classify_list.comp (C++: stages/monte_carlo/classify/classify.cpp).
#define CLASSIFY_WS_POSITION_UNIT 0
#define CLASSIFY_WS_NORMAL_UNIT 1
#define CLASSIFY_LEVELS_UNIT 2      // the N-buffer (2D array texture)
#define CLASSIFY_MINMAX_UNIT 3      // or the min-max mipmap's levels (minmax.glsl),
#define CLASSIFY_NEAR_UNIT 4        // whose level 0 is the near
#define CLASSIFY_FAR_UNIT 5         // and far layers
#define CLASSIFY_MASK_UNIT 0        // classify_list.comp: the mask classify.frag wrote
#define CLASSIFY_ITERATIONS_LOCATION 1
#define CLASSIFY_UMBRA_TEST_LOCATION 2
#define CLASSIFY_MINMAX_CELLS_LOCATION 3  // int: cells per axis over the min-max mipmap
                                          // (classify.minmax_cells; its program only)

#define CLASSIFY_COUNTS_BINDING 2
#define CLASSIFY_CLASS_COUNT 5
struct ClassifyCounts {
  uint pixels[8];  // indexed by CLASS_*; 5..7 unused (padding to 32 bytes)
};

// The pixels that still need rays (penumbra and umbra): a std430 buffer of uint count, the
// trace's indirect dispatch command (3 uints: groups of CLASSIFY_TRACE_GROUP pixels, 1, 1,
// at byte CLASSIFY_LIST_DISPATCH_OFFSET), then uint pixels[] packed x | y << 16; written by
// classify, read by trace, so the trace pass runs over them alone (thesis Fig 3.8: "full
// calculations are only performed in blue areas"), dispatched by the GPU's own count.
// Frame buffer name "classify.tracedPixels".
#define CLASSIFY_LIST_BINDING 3
#define CLASSIFY_LIST_HEADER_BYTES 16
#define CLASSIFY_LIST_DISPATCH_OFFSET 4
#define CLASSIFY_TRACE_GROUP 64  // trace.comp's invocations per group
