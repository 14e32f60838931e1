// The pictures of the hash statistics (docs/hash_stats.md), as float images in GL order (bottom row
// first) with the display hint a view or the PNG export applies: the `hash_stats` stage
// uploads them as its outputs, `penumbra hash-stats` writes them as PNG and EXR.
#pragma once
#include <vector>

#include "core/stage.h"
#include "stats/hash_stats.h"

struct StatsImage {
  int width = 0, height = 0;
  std::vector<float> values;  // one channel
  DisplayHint hint;
};

// 64 x 64 pair cells (x bucket right, y bucket up), count / expected: 1 is uniform.
StatsImage pairsImage(const hashstats::Result& result);
// 32 x 32 avalanche matrix c_ij, input bit i from the top row down, output bit j left to
// right: 0.5 everywhere is ideal, the identity hash shows a diagonal.
StatsImage avalancheImage(const hashstats::Result& result);
// 32 bars (bit 0 left), 8 texels wide, up or down from the middle by the bit's monobit
// z-score (full height at |z| = 8); |z| > 3 is unlikely for a fair bit.
StatsImage bitBiasImage(const hashstats::Result& result);
// Tests (rows, kTestNames order from the top) x keys (columns), kVerdictCell texels square
// each: 0 passed, 0.5 weak, 1 failed (dieharder's verdicts); not applicable shows as -1.
inline constexpr int kVerdictCell = 16;
StatsImage verdictImage(const hashstats::KeyedResult& keyed);
// Nearest-neighbour enlargement, as RGB8 top row first (for the PNG files).
std::vector<std::uint8_t> enlargedRgb(const StatsImage& image, int scale);
