// The hash statistics (docs/hash_stats.md): the distributions against published quantiles, every
// GPU statistic against the independent CPU computation of tests/support/hash_stats_oracle on the
// same numbers, and known answers (constant, counter, identity, std::mt19937).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "gl/hash_kind.h"
#include "stats/hash_stats_gpu.h"
#include "support/gl_test.h"
#include "support/hash_stats_oracle.h"

using namespace hashstats;

namespace {

const TestResult& test(const Result& result, const std::string& name) {
  for (const TestResult& t : result.tests)
    if (t.name == name) return t;
  throw std::out_of_range(name);
}

// GPU counts and sums against the oracle on the same samples.
void expectEqualToOracle(const Raw& raw, const statsref::Oracle& o, const std::string& what) {
  SCOPED_TRACE(what);
  for (int k = 0; k < HASH_STATS_BUCKETS; ++k) ASSERT_EQ(raw.counts[k], o.buckets[k]) << k;
  for (int k = 0; k < 4096; ++k) ASSERT_EQ(raw.counts[HASH_STATS_COUNT_PAIRS + k], o.pairs[k]) << k;
  for (int b = 0; b < 32; ++b) ASSERT_EQ(raw.counts[HASH_STATS_COUNT_BITS + b], o.ones[b]) << b;
  const Result result = analyze(raw);
  const double n = double(raw.samples);
  EXPECT_NEAR(test(result, "uniformity").statistic, o.chiBuckets, 1e-9 * o.chiBuckets + 1e-9);
  EXPECT_NEAR(test(result, "pairs_2d").statistic, o.chiPairs, 1e-9 * o.chiPairs + 1e-9);
  EXPECT_NEAR(test(result, "bit_bias").statistic, o.chiBits, 1e-9 * o.chiBits + 1e-9);
  // Float moments of 64 samples per invocation, joined in double.
  EXPECT_NEAR(test(result, "serial_right").statistic / std::sqrt(n), o.rRight, 2e-5);
  EXPECT_NEAR(test(result, "serial_frame").statistic / std::sqrt(n), o.rFrame, 2e-5);
  EXPECT_NEAR(test(result, "serial_next").statistic / std::sqrt(raw.next.n), o.rNext, 2e-5);
  EXPECT_EQ(int(raw.fipsBlocks.size() / HASH_STATS_FIPS_STRIDE), o.fipsBlocks);
  if (o.fipsBlocks > 0) {
    EXPECT_EQ(test(result, "fips_monobit").failedBlocks, o.monobitFails);
    EXPECT_EQ(test(result, "fips_poker").failedBlocks, o.pokerFails);
    EXPECT_EQ(test(result, "fips_runs").failedBlocks, o.runsFails);
    EXPECT_NEAR(test(result, "fips_runs").statistic, o.runsZ, 1e-9);
  }
}

}  // namespace

// Quantiles from statistical tables: chi-square(1) 3.841459 and chi-square(10) 18.307038 at
// 5%; chi-square(2) has the closed form exp(-x/2); the normal 1.959964 at 5% two-sided.
TEST(HashStatsMath, DistributionsMatchTables) {
  EXPECT_NEAR(chiSquareUpperP(3.841458820694124, 1), 0.05, 1e-9);
  EXPECT_NEAR(chiSquareUpperP(18.307038053275146, 10), 0.05, 1e-9);
  EXPECT_NEAR(chiSquareUpperP(0.2107210313156526, 2), 0.9, 1e-9);
  for (double x : {0.5, 3.0, 40.0}) EXPECT_NEAR(chiSquareUpperP(x, 2), std::exp(-x / 2), 1e-12);
  // Large dof: Wilson-Hilferty puts the median of chi-square(4095) at 4095 (1 - 2/(9*4095))^3.
  EXPECT_NEAR(chiSquareUpperP(4095 * std::pow(1 - 2.0 / (9 * 4095), 3), 4095), 0.5, 1e-4);
  EXPECT_NEAR(normalTwoSidedP(1.959963984540054), 0.05, 1e-12);
  // KS: evenly spread values are uniform; values crowded near 0 are not.
  std::vector<double> even, crowded;
  for (int i = 0; i < 100; ++i) even.push_back((i + 0.5) / 100), crowded.push_back(i / 400.0);
  double d = 0;
  EXPECT_GT(ksUniformP(even, &d), 0.99);
  EXPECT_NEAR(d, 0.005, 1e-12);
  EXPECT_LT(ksUniformP(crowded, &d), 1e-6);
  EXPECT_NEAR(d, 0.7525, 1e-12);
  // dieharder's verdicts and the thesis's interval.
  EXPECT_EQ(dieharderVerdict(0.5), Verdict::Passed);
  EXPECT_EQ(dieharderVerdict(0.004), Verdict::Weak);
  EXPECT_EQ(dieharderVerdict(0.9999999), Verdict::Failed);
  EXPECT_TRUE(thesisPass(0.01) && !thesisPass(0.009) && !thesisPass(0.995));
}

// Every statistic of the GPU passes equals the oracle's on the same numbers: hashes good and
// bad over every pattern (one chunk), the uploaded path, and the avalanche counts.
TEST(HashStatsGpu, EveryStatisticEqualsTheCpuComputation) {
  headlessContext();
  GpuHashStats gpu;
  const std::uint32_t count = 40000, key = 0xABCDu;
  const std::pair<int, int> cases[] = {
      {HASH_MD5_16, HASH_PATTERN_LINEAR}, {HASH_PCG3D, HASH_PATTERN_PIXELS},
      {HASH_MD5_4, HASH_PATTERN_MORTON},  {HASH_LCG15, HASH_PATTERN_FRAMES},
      {HASH_LCG32, HASH_PATTERN_PIXELS},  {HASH_XXHASH32, HASH_PATTERN_LINEAR}};
  for (auto [kind, pattern] : cases) {
    const std::string what = std::string(kHashKindNames[kind]) + " pattern " + std::to_string(pattern);
    const auto samples = statsref::samples(kind, pattern, count, key);
    const statsref::Oracle oracle = statsref::compute(samples, HASH_STATS_CHUNK);
    expectEqualToOracle(gpu.run(kind, pattern, count, key), oracle, what + " (generated)");
    expectEqualToOracle(gpu.runUploaded(samples), oracle, what + " (uploaded)");
    const Raw raw = gpu.run(kind, pattern, HASH_STATS_AVALANCHE_INPUTS, key);
    EXPECT_EQ(raw.avalancheInputs, HASH_STATS_AVALANCHE_INPUTS);
    const auto flips = statsref::avalanche(kind, pattern, HASH_STATS_AVALANCHE_INPUTS, key);
    for (int k = 0; k < HASH_STATS_FLIPS_TOTAL; ++k) ASSERT_EQ(raw.flips[k], flips[k]) << what << " cell " << k;
  }
}

// Across a chunk boundary (next-sample pairs and FIPS blocks restart per chunk).
TEST(HashStatsGpu, ChunksJoinLikeTheOracleSays) {
  headlessContext();
  GpuHashStats gpu;
  const std::uint32_t count = HASH_STATS_CHUNK + 20000;
  const auto samples = statsref::samples(HASH_PCG3D, HASH_PATTERN_LINEAR, count, 7);
  const statsref::Oracle oracle = statsref::compute(samples, HASH_STATS_CHUNK);
  EXPECT_EQ(oracle.fipsBlocks, 1600 + 32);
  expectEqualToOracle(gpu.run(HASH_PCG3D, HASH_PATTERN_LINEAR, count, 7), oracle, "pcg3d 1.02M");
}

// Known answers. A constant stream fails uniformity, pairs, bits and avalanche (nothing
// flips); the plain counter (identity on 1, 2, ..., n) fails uniformity and avalanche, and
// its avalanche matrix is exactly the identity: flipping input bit i flips output bit i only.
TEST(HashStatsKnownAnswers, ConstantAndCounterFailIdentityIsDiagonal) {
  headlessContext();
  GpuHashStats gpu;
  const Result constant = analyze(gpu.run(HASH_STATS_CONSTANT, HASH_PATTERN_LINEAR, 1 << 16, 0));
  for (const char* name : {"uniformity", "pairs_2d", "bit_bias", "avalanche", "serial_next"})
    EXPECT_EQ(test(constant, name).verdict(), Verdict::Failed) << "constant " << name;
  for (double c : constant.avalanche) ASSERT_EQ(c, 0.0);

  const Result counter = analyze(gpu.run(HASH_STATS_IDENTITY, HASH_PATTERN_LINEAR, 1 << 16, 0));
  for (const char* name : {"uniformity", "pairs_2d", "bit_bias", "avalanche", "serial_next"})
    EXPECT_EQ(test(counter, name).verdict(), Verdict::Failed) << "counter " << name;
  for (int i = 0; i < 32; ++i)
    for (int j = 0; j < 32; ++j)
      ASSERT_EQ(counter.avalanche[i * 32 + j], i == j ? 1.0 : 0.0) << i << "," << j;
  EXPECT_NEAR(counter.avalancheBias, 0.5, 1e-12);
  // Inputs 1..65536: bits 0-15 are clear in half of them (bit 16 in all but one), bits 17-31
  // in all.
  const Raw raw = gpu.run(HASH_STATS_IDENTITY, HASH_PATTERN_LINEAR, 1 << 16, 0);
  EXPECT_EQ(raw.flips[HASH_STATS_FLIPS_INPUTS + 0], 32768u);
  EXPECT_EQ(raw.flips[HASH_STATS_FLIPS_INPUTS + 15], 32768u);
  EXPECT_EQ(raw.flips[HASH_STATS_FLIPS_INPUTS + 16], 65535u);
  EXPECT_EQ(raw.flips[HASH_STATS_FLIPS_INPUTS + 31], 65536u);
}

// std::mt19937 words uploaded through the same path: over 100 keys (generator seeds) of 2^16
// samples, 9 tests each (no avalanche for a stream), every p-value should fall outside the
// thesis's [0.01, 0.99] with probability 0.02 (18 expected of 900, sd 4.2), be dieharder-WEAK
// with probability 0.01 and FAILED with 2e-6; and the 100 p-values of each test should pass
// a KS test of uniformity.
TEST(HashStatsKnownAnswers, Mt19937PassesAtTheExpectedRate) {
  headlessContext();
  GpuHashStats gpu;
  const int keys = 100;
  std::vector<Result> perKey;
  for (int key = 0; key < keys; ++key) {
    std::mt19937 random(1000 + key);
    std::vector<glm::uvec4> samples(1 << 16);
    for (auto& s : samples) s = {random(), random(), random(), random()};
    perKey.push_back(analyze(gpu.runUploaded(samples)));
  }
  int outside = 0, weak = 0, failed = 0, pValues = 0;
  for (const Result& result : perKey)
    for (const TestResult& t : result.tests) {
      if (std::isnan(t.p)) continue;
      ++pValues;
      outside += !thesisPass(t.p);
      weak += t.verdict() == Verdict::Weak;
      failed += t.verdict() == Verdict::Failed;
    }
  EXPECT_EQ(pValues, 900);
  // Binomial(900, 0.02): P(X <= 5) = 2.9e-4, P(X >= 36) = 1.0e-4 (a false alarm 4e-4).
  EXPECT_GT(outside, 5);
  EXPECT_LT(outside, 36);
  EXPECT_LT(weak, 22);  // Binomial(900, 0.01): P(X >= 22) = 1.6e-4
  EXPECT_EQ(failed, 0);
  const KeyedResult keyed = combineKeys(perKey);
  for (size_t t = 0; t < keyed.ksP.size(); ++t) {
    if (std::isnan(keyed.ksP[t])) continue;  // avalanche: no function behind a stream
    EXPECT_GT(keyed.ksP[t], 1e-3) << kTestNames[t];
  }
  std::printf("mt19937, %d keys x 2^16: %d of %d p-values outside [0.01, 0.99], %d weak, %d failed\n",
              keys, outside, pValues, weak, failed);
}
