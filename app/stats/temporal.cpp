#include "stats/temporal.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

TemporalChange temporalChange(const std::vector<float>& method0, const std::vector<float>& method1,
                              const std::vector<float>& reference0,
                              const std::vector<float>& reference1,
                              const std::vector<std::uint8_t>& counted, float tolerance) {
  const std::size_t n = method0.size();
  if (method1.size() != n || reference0.size() != n || reference1.size() != n || counted.size() != n)
    throw std::invalid_argument("temporal change: the frames' arrays differ in size (" +
                                std::to_string(method0.size()) + ", " + std::to_string(method1.size()) +
                                ", " + std::to_string(reference0.size()) + ", " +
                                std::to_string(reference1.size()) + ", mask " +
                                std::to_string(counted.size()) + ")");
  TemporalChange result;
  double sumStable = 0, sumReference = 0, sumMethod = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!counted[i]) continue;
    const float m0 = method0[i], m1 = method1[i], r0 = reference0[i], r1 = reference1[i];
    if (!std::isfinite(m0) || !std::isfinite(m1) || !std::isfinite(r0) || !std::isfinite(r1)) continue;
    const double methodDelta = std::fabs(double(m1) - double(m0));
    const double referenceDelta = std::fabs(double(r1) - double(r0));
    ++result.counted;
    sumReference += referenceDelta;
    sumMethod += methodDelta;
    if (referenceDelta > double(tolerance)) continue;  // the truth moved here: not a stable pixel
    ++result.stable;
    sumStable += methodDelta;
    result.maxChange = std::max(result.maxChange, methodDelta);
  }
  if (result.stable) result.change = sumStable / double(result.stable);
  if (result.counted) {
    result.referenceChange = sumReference / double(result.counted);
    result.methodChange = sumMethod / double(result.counted);
  }
  return result;
}

std::vector<std::uint8_t> bothCounted(const std::vector<std::uint8_t>& a,
                                      const std::vector<std::uint8_t>& b, std::size_t pixels) {
  if (!a.empty() && a.size() != pixels)
    throw std::invalid_argument("temporal change: the first mask has " + std::to_string(a.size()) +
                                " pixels, not " + std::to_string(pixels));
  if (!b.empty() && b.size() != pixels)
    throw std::invalid_argument("temporal change: the second mask has " + std::to_string(b.size()) +
                                " pixels, not " + std::to_string(pixels));
  std::vector<std::uint8_t> both(pixels, 1);
  for (std::size_t i = 0; i < pixels; ++i)
    both[i] = std::uint8_t((a.empty() || a[i]) && (b.empty() || b[i]));
  return both;
}

TemporalSummary summarizeTemporal(const std::vector<TemporalChange>& changes) {
  TemporalSummary summary;
  for (const TemporalChange& pair : changes) {
    if (!pair.defined()) continue;
    ++summary.pairs;
    summary.meanChange += pair.change;
    summary.meanReferenceChange += pair.referenceChange;
    summary.meanMethodChange += pair.methodChange;
    summary.worstChange = std::max(summary.worstChange, pair.change);
    summary.worstPixel = std::max(summary.worstPixel, pair.maxChange);
  }
  if (summary.pairs) {
    summary.meanChange /= summary.pairs;
    summary.meanReferenceChange /= summary.pairs;
    summary.meanMethodChange /= summary.pairs;
  }
  return summary;
}
