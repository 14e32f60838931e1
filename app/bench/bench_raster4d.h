// `penumbra bench-raster4d`: stage raster4d (Wang et al. 2020) timed side by side with the
// Embree reference at the same light samples (uniform sampling, every core), in the shapes
// of the paper's tables: speed-up over ray tracing and time per step (Tables 1, 3), cost
// against light samples (Table 4) and light size (Table 5), the optimizations' effect
// (Table 2) and the pairing efficiency (Table 7). Medians of `frames` runs after one
// warm-up run, glFinish + steady clock. A benchmark program: it writes numbers, asserts
// nothing.
#pragma once
#include <string>

struct BenchRaster4dOptions {
  // The Markdown file to write (--out, required). The committed write-up,
  // docs/raster4d_speed.md, joins two runs' tables with notes on the paper and the machine,
  // so no run overwrites it by default.
  std::string out;
  std::string scenes = "cube,spheres,engine";
  // Scenes whose Table 2 variants (proj4, rejection off, row masks off, row culling off) are
  // timed; "" = every scene. Per-sample tests on a 91k-triangle scene take many minutes.
  std::string toggleScenes;
  int width = 256, height = 256, frames = 3;
};

int runBenchRaster4d(const BenchRaster4dOptions& options);
