// `penumbra bench-hierarchy` (docs/design.md#bench): the N-buffer against the min-max mipmap, back
// to back in one run (frames alternate between the two), per map size: hierarchy build time,
// memory, fetches per searched ray, trace time, and whether the visibilities agree. A benchmark
// program: it writes numbers, asserts nothing.
#pragma once
#include <string>
#include <vector>

struct BenchHierarchyOptions {
  // The Markdown file to write (--out, required); the table is printed too. The numbers
  // that decided the min-max mipmap are in docs/decisions/024-minmax-mipmap-levels.md.
  std::string out;
  int frames = 6, warmup = 1;
  int width = 640, height = 480;
  std::string scene = "cube";
  std::vector<int> maps = {512, 1024, 2048};
  std::vector<std::string> sets;  // applied to both hierarchies
};

int runBenchHierarchy(const BenchHierarchyOptions& options);
