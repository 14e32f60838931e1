// The hash_stats stage's panel (docs/hash_stats.md), drawn under the stage in the pipeline panel:
// the table of tests x p-values with dieharder's verdicts in colour, a comparison of every hash
// (GPU throughput measured), and the real battery: `penumbra hash | dieharder -g 200` on the
// DIEHARD tests in the background with progress and cancel, counted beside the thesis's.
#pragma once

class UiState;

void drawHashStatsPanel(UiState& state);
