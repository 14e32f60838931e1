#include "stats/hash_stats_views.h"

#include <algorithm>
#include <cmath>

#include "io/colormap.h"

StatsImage pairsImage(const hashstats::Result& result) {
  StatsImage image{HASH_STATS_PAIR_SIDE, HASH_STATS_PAIR_SIDE, {}, {0, 0, 2, Colormap::Perceptual}};
  image.values.assign(result.pairs.begin(), result.pairs.end());  // row = y bucket: GL order
  return image;
}

StatsImage avalancheImage(const hashstats::Result& result) {
  StatsImage image{32, 32, std::vector<float>(32 * 32, 0.5f), {0, 0, 1, Colormap::Diverging}};
  if (result.avalanche.empty()) return image;  // a stream: no function to flip
  for (int i = 0; i < 32; ++i)
    for (int j = 0; j < 32; ++j) image.values[(31 - i) * 32 + j] = float(result.avalanche[i * 32 + j]);
  return image;
}

StatsImage bitBiasImage(const hashstats::Result& result) {
  const int barWidth = 8, height = 128, middle = height / 2;
  StatsImage image{32 * barWidth, height, std::vector<float>(32 * barWidth * height, 0.0f),
                   {0, -8, 8, Colormap::Diverging}};
  for (int b = 0; b < 32; ++b) {
    const double z = std::clamp(result.bitZ[b], -8.0, 8.0);
    const int extent = int(std::lround(std::abs(z) / 8 * middle));
    for (int k = 0; k < extent; ++k) {
      const int row = z >= 0 ? middle + k : middle - 1 - k;
      for (int x = b * barWidth + 1; x < (b + 1) * barWidth - 1; ++x)
        image.values[row * image.width + x] = float(z);
    }
  }
  return image;
}

StatsImage verdictImage(const hashstats::KeyedResult& keyed) {
  const int tests = int(hashstats::kTestNames.size()), keys = int(keyed.perKey.size());
  const int cell = kVerdictCell;
  StatsImage image{keys * cell, tests * cell, std::vector<float>(size_t(keys) * tests * cell * cell),
                   {0, -1, 1, Colormap::Diverging}};
  for (int k = 0; k < keys; ++k)
    for (int t = 0; t < tests; ++t) {
      const auto verdict = keyed.perKey[k].tests[t].verdict();
      const float value = verdict == hashstats::Verdict::Passed ? 0.0f
                          : verdict == hashstats::Verdict::Weak ? 0.5f
                          : verdict == hashstats::Verdict::Failed ? 1.0f
                                                                  : -1.0f;
      for (int y = 0; y < cell; ++y)
        for (int x = 0; x < cell; ++x)
          image.values[size_t((tests - 1 - t) * cell + y) * image.width + k * cell + x] = value;
    }
  return image;
}

std::vector<std::uint8_t> enlargedRgb(const StatsImage& image, int scale) {
  const int width = image.width * scale, height = image.height * scale;
  std::vector<float> big(size_t(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      big[size_t(y) * width + x] = image.values[size_t(y / scale) * image.width + x / scale];
  return displayRgb8(big, width, height, 1, image.hint);
}
