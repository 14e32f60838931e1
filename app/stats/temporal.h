// Temporal stability of a shadow method (docs/decisions/120-temporal-stability.md): how much
// its visibility changes from one frame to the next where the exact visibility did not.
// Monte Carlo noise that "swims" under a per-frame key and shadow-map texels that "crawl"
// under a slowly moving occluder (thesis §4.1: "at much lower resolutions temporal aliasing
// becomes a problem") both show up as change where the truth holds still.
//
// Plain C++ over two frames' arrays, one float per pixel, row-major, the same size:
//   stable pixels S = counted in both frames and |reference1 - reference0| <= tolerance
//   change          = mean over S of |method1 - method0|           (defined when S is not empty)
//   referenceChange = mean over the counted pixels C of |reference1 - reference0|
//   methodChange    = mean over C of |method1 - method0|
//   ratio           = change / referenceChange (defined only when referenceChange > 0; on a
//                     static scene the truth never changes and only `change` is reported)
// A pixel with a non-finite value in any of the four arrays does not count.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

struct TemporalChange {
  double change = 0;           // mean |m1 - m0| over the stable pixels
  double maxChange = 0;        // max |m1 - m0| over the stable pixels
  double referenceChange = 0;  // mean |r1 - r0| over the counted pixels
  double methodChange = 0;     // mean |m1 - m0| over the counted pixels
  std::size_t counted = 0, stable = 0;
  bool defined() const { return stable > 0; }
  bool hasRatio() const { return stable > 0 && referenceChange > 0; }
  double ratio() const { return hasRatio() ? change / referenceChange : 0; }
};

// `counted`: nonzero where the pixel counts in both frames (bothCounted). Throws
// std::invalid_argument when the sizes differ.
TemporalChange temporalChange(const std::vector<float>& method0, const std::vector<float>& method1,
                              const std::vector<float>& reference0,
                              const std::vector<float>& reference1,
                              const std::vector<std::uint8_t>& counted, float tolerance = 0);

// Nonzero where both masks are (the pixels that count in both frames); an empty mask counts
// every pixel. Throws std::invalid_argument when both are given and their sizes differ.
std::vector<std::uint8_t> bothCounted(const std::vector<std::uint8_t>& a,
                                      const std::vector<std::uint8_t>& b, std::size_t pixels);

// Over a run of frames (one TemporalChange per consecutive pair; undefined pairs skipped):
//   meanChange, worstChange: mean and largest `change`; worstPixel: largest `maxChange` (one
//   pixel's jump: a texel popping shows here long before it moves the mean);
//   meanReferenceChange: mean `referenceChange` over the same pairs;
//   ratio = meanChange / meanReferenceChange, defined only when that is > 0.
struct TemporalSummary {
  int pairs = 0;  // pairs with a defined change
  double meanChange = 0, worstChange = 0, worstPixel = 0, meanReferenceChange = 0, meanMethodChange = 0;
  bool hasRatio() const { return pairs > 0 && meanReferenceChange > 0; }
  double ratio() const { return hasRatio() ? meanChange / meanReferenceChange : 0; }
};
TemporalSummary summarizeTemporal(const std::vector<TemporalChange>& changes);
