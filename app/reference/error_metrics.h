// Error of a method's visibility against the reference (docs/design.md#ground-truth), over the
// pixels that count: receivers inside the light's map (classify.mask neither background nor
// outside).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

struct ErrorMetrics {
  double rmse = 0;             // sqrt(mean (method - reference)^2), OIIO compare
  double max = 0;              // max |method - reference|, OIIO compare
  double meanAbsInShadow = 0;  // mean |error| over pixels with reference < 1 (Atty 2006 §4.2.1)
  double p99 = 0;              // 99th percentile of |error| (nearest rank)
  double meanSigned = 0;       // mean (method - reference): > 0 too bright, < 0 too dark
  std::size_t pixels = 0, pixelsInShadow = 0;
};

// The pixels that count, from classify.mask (one class per pixel): neither background nor
// outside the light's map; with `receiverFlag` (receivers.flag) only receiver-only objects'
// pixels (error.pixels = receivers, Atty 2006 §4.2.1). The error stage and a lesson's crop
// numbers both count this way.
std::vector<std::uint8_t> countedPixels(const std::vector<float>& mask,
                                        const std::vector<float>* receiverFlag = nullptr);

// `method` and `reference`: one float per pixel; `counted`: nonzero where the pixel counts.
// Fills `signedError` (method - reference, 0 where not counted) if given.
ErrorMetrics computeErrorMetrics(const std::vector<float>& method,
                                 const std::vector<float>& reference,
                                 const std::vector<std::uint8_t>& counted, int width, int height,
                                 std::vector<float>* signedError = nullptr);
