// Shared by the error passes (layouts: stages/ground_truth/error/error_layout.h): which pixels count and their
// error, computed identically by every pass that reads it.
#include "stages/ground_truth/error/error_layout.h"
#include "shared/classes.h"
layout(binding = ERROR_METHOD_UNIT) uniform sampler2D methodTexture;
layout(binding = ERROR_TRUTH_UNIT) uniform sampler2D truthTexture;
layout(binding = ERROR_MASK_UNIT) uniform sampler2D maskTexture;
layout(binding = ERROR_FLAG_UNIT) uniform sampler2D flagTexture;
layout(location = ERROR_RECEIVERS_ONLY_LOCATION) uniform int uReceiversOnly;

// Whether `pixel` counts (docs/design.md#ground-truth; the CPU's rule is countedPixels in
// app/reference/error_metrics.cpp): a receiver inside the light's map (its class neither
// background nor outside), and with error.pixels = receivers a receiver-only object's pixel
// (Atty et al. 2006 §4.2.1 measure on the receiver). Then `difference` = method - truth and
// `truth` the ground truth's visibility there.
bool countedError(ivec2 pixel, out float difference, out float truth) {
  difference = 0.0;
  truth = 1.0;
  int pixelClass = int(floor(texelFetch(maskTexture, pixel, 0).r + 0.5));  // classes are whole
  if (pixelClass == CLASS_BACKGROUND || pixelClass == CLASS_OUTSIDE) return false;
  if (uReceiversOnly != 0 && !(texelFetch(flagTexture, pixel, 0).r > 0.5)) return false;
  truth = texelFetch(truthTexture, pixel, 0).r;
  difference = texelFetch(methodTexture, pixel, 0).r - truth;
  return true;
}

// A non-negative float's bits, whose unsigned order is the float order (for max and select).
uint absoluteBits(float difference) { return floatBitsToUint(abs(difference)); }
