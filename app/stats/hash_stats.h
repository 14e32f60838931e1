// DIEHARD-like statistics of a hash (thesis §3.1, §4.3, Appendix A; docs/hash_stats.md; dieharder's
// verdicts; FIPS 140-2 §4.9.1): from the counts and sums the GPU passes leave
// (app/stats/hash_stats_gpu.h), every statistic and p-value in double on the CPU.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "shared/hash_stats_layout.h"

namespace hashstats {

// Input patterns, indexed by HASH_PATTERN_* (also the option index of hash_stats.pattern).
inline const std::array<const char*, HASH_PATTERN_COUNT> kPatternNames = {"linear", "pixels",
                                                                          "morton", "frames"};
int patternFromName(const std::string& name);  // -1 when unknown
std::string patternList();                     // "linear, pixels, morton, frames"

// Means and centred (co)moments of n pairs (a, b), joined in double (Chan, Golub & LeVeque
// 1979: exact for any split, no cancellation of large sums).
struct Comoments {
  double n = 0, meanA = 0, meanB = 0, m2A = 0, m2B = 0, coAB = 0;
  void join(const Comoments& other);
  double correlation() const;  // Pearson r; 1 when a side is constant (fully predictable)
};

// What the GPU passes leave for one key: integer counts and the per-invocation moments
// joined in double.
struct Raw {
  std::uint64_t samples = 0;
  std::vector<std::uint32_t> counts = std::vector<std::uint32_t>(HASH_STATS_COUNT_TOTAL, 0);
  Comoments next, right, frame;  // (c, next c), (c, right-hand c), (c, next-frame c)
  std::vector<std::uint32_t> fipsBlocks;  // HASH_STATS_FIPS_STRIDE words per block
  std::uint32_t avalancheInputs = 0;      // 0: no avalanche (samples uploaded, no function)
  // Flip counts (32 x 32, input bit major), then the inputs counted per input bit.
  std::vector<std::uint32_t> flips = std::vector<std::uint32_t>(HASH_STATS_FLIPS_TOTAL, 0);
};

// dieharder's verdicts (its defaults: weak outside [0.005, 0.995], failed outside
// [1e-6, 1 - 1e-6]); NotApplicable where the test could not run (too few samples).
enum class Verdict { Passed, Weak, Failed, NotApplicable };
Verdict dieharderVerdict(double p);
const char* verdictName(Verdict verdict);  // "PASSED", "WEAK", "FAILED", "n/a"
// The thesis's criterion (§3.1): p in [0.01, 0.99].
bool thesisPass(double p);

struct TestResult {
  std::string name;       // "pairs_2d"
  double statistic = 0;   // chi-square, z or D as `detail` says
  double p = 0;           // NaN where not applicable
  std::string detail;     // "chi2 = 4123.4, 4095 dof", "3 of 1677 blocks fail FIPS"
  int failedBlocks = -1;  // FIPS tests: blocks outside FIPS 140-2's intervals
  Verdict verdict() const { return dieharderVerdict(p); }
};

// The tests in table order; each Result holds them in this order.
inline const std::array<const char*, 10> kTestNames = {
    "uniformity", "pairs_2d",  "bit_bias",     "serial_next", "serial_right",
    "serial_frame", "avalanche", "fips_monobit", "fips_poker",  "fips_runs"};

struct Result {
  std::vector<TestResult> tests;
  std::array<double, 32> bitZ{};  // monobit z-score of each bit of word x
  std::vector<double> avalanche;  // c_ij = P(bit j of x flips | input bit i flips), i-major
  double avalancheBias = 0;       // RMS of c_ij - 1/2
  double avalancheNoise = 0;      // the RMS an ideal hash shows with these inputs (~1/(2 sqrt(A)))
  std::vector<double> pairs;      // 64 x 64 cell counts / expected count, row = y bucket
};

Result analyze(const Raw& raw);

// Distributions (double precision): upper tail of chi-square with `dof` degrees of freedom,
// two-sided normal tail, and the Kolmogorov-Smirnov test of values against U(0,1).
double chiSquareUpperP(double chiSquare, double dof);
double normalTwoSidedP(double z);
double ksUniformP(std::vector<double> values, double* statistic = nullptr);

// FIPS 140-2 §4.9.1 acceptance intervals for one 20,000-bit block.
bool fipsMonobitPasses(std::uint32_t ones);
bool fipsPokerPasses(const std::uint32_t* nibbleCounts16);
bool fipsRunsPass(const std::uint32_t* runs12, std::uint32_t longestRun);

// K keys: one Result per key; `ksP[t]` is the KS p-value of test t's K p-values (NaN when
// K < 2 or the test does not apply).
struct KeyedResult {
  std::vector<Result> perKey;
  std::vector<double> ksP, ksD;
};
KeyedResult combineKeys(std::vector<Result> perKey);

}  // namespace hashstats
