// The hash_stats stage's panel (docs/hash_stats.md), drawn under the stage in the pipeline panel:
// the table of tests x p-values with dieharder's verdicts in colour, a comparison of every hash
// (GPU throughput measured), and the real battery: `penumbra hash | dieharder -g 200` on the
// DIEHARD tests in the background with progress and cancel, counted beside the thesis's.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "stats/dieharder_run.h"
#include "stats/hash_stats.h"

class UiState;

// What the panel keeps between frames (UiState::PanelMemory::hashStats): the last
// comparison of every hash, and the dieharder run in the background (cancelled and joined
// when the state goes).
struct HashStatsPanelState {
  // Every hash on the stage's pattern, 2^16 samples each, with measured throughput.
  struct Comparison {
    std::vector<std::string> hashes;
    std::vector<hashstats::Result> results;
    std::vector<double> hashesPerSecond;
  };
  std::unique_ptr<Comparison> comparison;
  std::unique_ptr<DieharderRun> run;
};

void drawHashStatsPanel(UiState& state);
