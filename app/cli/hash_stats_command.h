// `penumbra hash-stats`: the DIEHARD-like statistics of the `hash_stats` stage (docs/hash_stats.md;
// thesis §3.1, §4.3, Appendix A) from the command line, and the real battery:
//   penumbra hash-stats [--hash H|all] [--pattern P|all] [--count N] [--keys K] [--key K0]
//                       [--out DIR] [--dieharder]
// prints the table (every hash x every test, with measured GPU throughput, for --hash all)
// and with --out writes hash_stats.md, hash_stats.json and per hash and pattern the pair
// histogram, avalanche matrix, per-bit bias bars and verdicts as PNG (as displayed) and EXR
// (raw). --dieharder runs `penumbra hash --hash H | dieharder -g 200 -d N` over the DIEHARD
// tests for each selected hash and adds the counts beside the thesis's.
#pragma once
#include <cstdint>
#include <string>

struct HashStatsOptions {
  std::string hash = "all";       // a hash name or "all"
  std::string pattern = "linear"; // a pattern name or "all"
  std::uint64_t count = 1u << 20; // samples per key: 1024 .. 2^24
  int keys = 1;                   // 1 .. 64: K keys key0, key0 + 1, ...; KS over them
  std::uint32_t key = 0;
  std::string out;                // directory; "" prints the table only
  bool dieharder = false;
};

// "" when valid, else what is wrong (naming the valid values).
std::string checkHashStatsOptions(const HashStatsOptions& options);
// Exit status: 0, 2 for bad options, 1 for internal failures (no GL, dieharder missing or
// failing, unwritable output).
int runHashStatsCommand(const HashStatsOptions& options);
