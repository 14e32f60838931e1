// Stage `error`, the 99th percentile of |error| (nearest rank), one radix pass per dispatch:
// the bits of a non-negative float sort as the float, so the value at the rank is found
// ERROR_RADIX_BITS bits at a time from the highest. This pass counts, per bin of the
// current bits, the counted pixels whose higher bits equal those already found
// (ErrorTotals.select.x); error_reduce.comp then picks the bin holding the rank. The
// group's histogram is built in shared memory, then added to the global one.
#include "error.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(location = ERROR_RADIX_PASS_LOCATION) uniform int uPass;
layout(std430, binding = ERROR_TOTALS_BINDING) readonly buffer Totals { ErrorTotals totals; };
layout(std430, binding = ERROR_HISTOGRAM_BINDING) buffer Histogram { uint histogram[]; };

shared uint groupHistogram[ERROR_RADIX_BINS];

void main() {
  uint me = gl_LocalInvocationIndex;
  for (uint bin = me; bin < uint(ERROR_RADIX_BINS); bin += 64u) groupHistogram[bin] = 0u;
  barrier();
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = textureSize(maskTexture, 0);
  float difference, truth;
  if (pixel.x < size.x && pixel.y < size.y && countedError(pixel, difference, truth)) {
    uint bits = absoluteBits(difference);
    int shift = 32 - ERROR_RADIX_BITS * (uPass + 1);  // the current bits' lowest position
    bool sharesHigherBits = uPass == 0 || (bits >> uint(shift + ERROR_RADIX_BITS)) == totals.select.x;
    if (sharesHigherBits) atomicAdd(groupHistogram[(bits >> uint(shift)) & uint(ERROR_RADIX_BINS - 1)], 1u);
  }
  barrier();
  for (uint bin = me; bin < uint(ERROR_RADIX_BINS); bin += 64u)
    if (groupHistogram[bin] != 0u) atomicAdd(histogram[bin], groupHistogram[bin]);
}
