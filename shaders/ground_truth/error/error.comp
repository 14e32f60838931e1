// Stage `error`, per pixel (Atty et al. 2006 §4.2.1): the method's visibility minus the
// ground truth's where the pixel counts (error.glsl), written as the signed and the
// absolute error images, and this 8 x 8 group's sums for the statistics: pixels, pixels in
// shadow (truth < 1), the sum of the signed error, of |error| in shadow, of error^2 (for the
// RMSE) and the largest |error|. The sums are reduced in shared memory, the group's record
// written once (no per-pixel atomics); error_reduce.comp then adds the records.
#include "error.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = ERROR_SIGNED_IMAGE, r32f) uniform writeonly image2D signedImage;
layout(binding = ERROR_ABSOLUTE_IMAGE, r32f) uniform writeonly image2D absoluteImage;
layout(std430, binding = ERROR_GROUP_SUMS_BINDING) writeonly buffer GroupSums { ErrorSums groupSums[]; };

const uint kInvocations = 64u;
shared uint pixelsShared[kInvocations], inShadowShared[kInvocations], maxShared[kInvocations];
shared double signedShared[kInvocations], absInShadowShared[kInvocations],
    squaresShared[kInvocations];

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = textureSize(maskTexture, 0);
  uint me = gl_LocalInvocationIndex;
  float difference = 0.0, truth = 1.0;
  bool counted = false;
  if (pixel.x < size.x && pixel.y < size.y) {
    counted = countedError(pixel, difference, truth);
    imageStore(signedImage, pixel, vec4(difference));
    imageStore(absoluteImage, pixel, vec4(abs(difference)));
  }
  bool inShadow = counted && truth < 1.0;
  pixelsShared[me] = counted ? 1u : 0u;
  inShadowShared[me] = inShadow ? 1u : 0u;
  maxShared[me] = counted ? absoluteBits(difference) : 0u;
  signedShared[me] = double(difference);
  absInShadowShared[me] = inShadow ? double(abs(difference)) : 0.0lf;
  squaresShared[me] = double(difference) * double(difference);  // exact: 48 bits of 53
  barrier();
  // Pairwise in shared memory: after the step of width s, invocation i < s holds the sums of
  // invocations i, i + s, i + 2s, ... of the group.
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
  ErrorSums sums;
  sums.counts = uvec4(pixelsShared[0], inShadowShared[0], maxShared[0], 0u);
  sums.sums = uvec4(unpackDouble2x32(signedShared[0]), unpackDouble2x32(absInShadowShared[0]));
  sums.squares = uvec4(unpackDouble2x32(squaresShared[0]), 0u, 0u);
  groupSums[gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x] = sums;
}
