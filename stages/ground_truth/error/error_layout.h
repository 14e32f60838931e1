// Layouts of stage `error` (stages/ground_truth/error/error.cpp; shaders error.comp,
// error_histogram.comp, error_reduce.comp; shaders/ground_truth/error/error.glsl), read by C++ (static_assert'ed
// there) and GLSL. The error and its statistics are computed on the GPU and read after the
// frame (Frame::readAfterFrame): per pixel one invocation in 8 x 8 groups, each group's sums
// reduced in shared memory into one ErrorSums record, the records summed by one group of
// ERROR_REDUCE_GROUP invocations; the 99th percentile selected exactly by a radix select
// over the bits of |error| (ERROR_RADIX_PASSES passes of ERROR_RADIX_BITS bits).
#define ERROR_METHOD_UNIT 0  // sampler2D: the method's visibility
#define ERROR_TRUTH_UNIT 1   // sampler2D: the ground truth's visibility
#define ERROR_MASK_UNIT 2    // sampler2D: classify.mask (one class per pixel, shared/classes.h)
#define ERROR_FLAG_UNIT 3    // sampler2D: receivers.flag (read only with error.pixels = receivers)
#define ERROR_SIGNED_IMAGE 0    // r32f: method - truth, 0 where the pixel does not count
#define ERROR_ABSOLUTE_IMAGE 1  // r32f: |method - truth|, 0 where the pixel does not count
#define ERROR_GROUP_SUMS_BINDING 0  // ErrorSums per 8 x 8 group of error.comp (row-major groups)
#define ERROR_TOTALS_BINDING 1      // ErrorTotals: the run's statistics (read after the frame)
#define ERROR_HISTOGRAM_BINDING 2   // uint per radix bin of the current pass
#define ERROR_RECEIVERS_ONLY_LOCATION 0  // uniform int: 1 = only receiver-only objects count
#define ERROR_RADIX_PASS_LOCATION 1      // uniform int: the radix pass (0 = the highest bits)
#define ERROR_REDUCE_MODE_LOCATION 2     // uniform int: ERROR_REDUCE_SUMS or ERROR_REDUCE_SELECT
#define ERROR_REDUCE_SUMS 0    // error_reduce.comp: sum the groups' records into the totals
#define ERROR_REDUCE_SELECT 1  // error_reduce.comp: pick the percentile's bin of one pass
#define ERROR_REDUCE_GROUP 256
#define ERROR_RADIX_BITS 8
#define ERROR_RADIX_BINS 256  // 1 << ERROR_RADIX_BITS
#define ERROR_RADIX_PASSES 4  // 32 bits of a float

// Sums over the pixels that count (one group's, or all of them). A double is held as its
// two 32-bit halves (packDouble2x32 / unpackDouble2x32: x the low word, y the high word).
struct ErrorSums {
  uvec4 counts;   // x = pixels, y = pixels in shadow (truth < 1), z = bits of max |error|
  uvec4 sums;     // xy = sum of (method - truth), zw = sum of |error| over pixels in shadow
  uvec4 squares;  // xy = sum of (method - truth)^2 (each square exact in double), zw unused
};

struct ErrorTotals {
  ErrorSums sums;
  // The radix select of the 99th percentile (nearest rank, rank = ceil(0.99 n) - 1 =
  // n - floor(n / 100) - 1 from the smallest, n = pixels): x = the high bits of the value
  // found so far, y = its rank among the values that share them, z = passes done.
  uvec4 select;
};
