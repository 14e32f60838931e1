// Stage `error`, one group of ERROR_REDUCE_GROUP invocations, two jobs:
// ERROR_REDUCE_SUMS: the run's totals from the 8 x 8 groups' records of error.comp (each
//   invocation adds every ERROR_REDUCE_GROUP-th record, then the partial sums are reduced
//   pairwise in shared memory), and the rank of the 99th percentile, ceil(0.99 n) - 1.
// ERROR_REDUCE_SELECT: after a radix pass (error_histogram.comp), the bin that holds the
//   rank: an inclusive prefix sum of the bins (Hillis-Steele), the one bin whose range
//   [sum below, sum through) contains the rank appends its bits to the value found so far
//   and leaves the rank within it. After ERROR_RADIX_PASSES passes, the value's bits.
#include "stages/ground_truth/error/error_layout.h"
layout(local_size_x = ERROR_REDUCE_GROUP) in;
layout(location = ERROR_REDUCE_MODE_LOCATION) uniform int uMode;
layout(std430, binding = ERROR_GROUP_SUMS_BINDING) readonly buffer GroupSums { ErrorSums groupSums[]; };
layout(std430, binding = ERROR_TOTALS_BINDING) buffer Totals { ErrorTotals totals; };
layout(std430, binding = ERROR_HISTOGRAM_BINDING) readonly buffer Histogram { uint histogram[]; };

const uint kInvocations = uint(ERROR_REDUCE_GROUP);
shared uint pixelsShared[kInvocations], inShadowShared[kInvocations], maxShared[kInvocations];
shared double signedShared[kInvocations], absInShadowShared[kInvocations],
    squaresShared[kInvocations];

void sumGroups() {
  uint me = gl_LocalInvocationIndex;
  uint pixels = 0u, inShadow = 0u, maxBits = 0u;
  double signedSum = 0.0lf, absInShadow = 0.0lf, squares = 0.0lf;
  for (uint group = me; group < uint(groupSums.length()); group += kInvocations) {
    ErrorSums record = groupSums[group];
    pixels += record.counts.x;
    inShadow += record.counts.y;
    maxBits = max(maxBits, record.counts.z);
    signedSum += packDouble2x32(record.sums.xy);
    absInShadow += packDouble2x32(record.sums.zw);
    squares += packDouble2x32(record.squares.xy);
  }
  pixelsShared[me] = pixels, inShadowShared[me] = inShadow, maxShared[me] = maxBits;
  signedShared[me] = signedSum, absInShadowShared[me] = absInShadow, squaresShared[me] = squares;
  barrier();
  for (uint width = kInvocations / 2u; width > 0u; width /= 2u) {
    if (me < width) {
      pixelsShared[me] += pixelsShared[me + width];
      inShadowShared[me] += inShadowShared[me + width];
      maxShared[me] = max(maxShared[me], maxShared[me + width]);
      signedShared[me] += signedShared[me + width];
      absInShadowShared[me] += absInShadowShared[me + width];
      squaresShared[me] += squaresShared[me + width];
    }
    barrier();
  }
  if (me != 0u) return;
  uint n = pixelsShared[0];
  totals.sums.counts = uvec4(n, inShadowShared[0], maxShared[0], 0u);
  totals.sums.sums = uvec4(unpackDouble2x32(signedShared[0]), unpackDouble2x32(absInShadowShared[0]));
  totals.sums.squares = uvec4(unpackDouble2x32(squaresShared[0]), 0u, 0u);
  // Nearest rank from the smallest: ceil(0.99 n) - 1 = n - floor(n / 100) - 1 (n > 0).
  totals.select = uvec4(0u, n > 0u ? n - n / 100u - 1u : 0u, 0u, 0u);
}

shared uint binsShared[kInvocations];

void selectBin() {
  uint me = gl_LocalInvocationIndex;
  uint count = me < uint(ERROR_RADIX_BINS) ? histogram[me] : 0u;
  binsShared[me] = count;
  barrier();
  for (uint offset = 1u; offset < kInvocations; offset *= 2u) {  // inclusive prefix sum
    uint add = me >= offset ? binsShared[me - offset] : 0u;
    barrier();
    binsShared[me] += add;
    barrier();
  }
  uint through = binsShared[me], below = through - count;
  uint rank = totals.select.y;
  barrier();  // every invocation has read the rank before one rewrites it
  if (me < uint(ERROR_RADIX_BINS) && below <= rank && rank < through)
    totals.select = uvec4((totals.select.x << uint(ERROR_RADIX_BITS)) | me, rank - below,
                          totals.select.z + 1u, 0u);
}

void main() {
  if (uMode == ERROR_REDUCE_SUMS) sumGroups();
  else selectBin();
}
