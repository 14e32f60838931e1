#include "stats/hash_stats.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_gamma.h>

namespace hashstats {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string format(const char* pattern, double a, double b = 0, double c = 0) {
  char text[160];
  std::snprintf(text, sizeof text, pattern, a, b, c);
  return text;
}

TestResult correlationTest(const char* name, const Comoments& moments) {
  if (moments.n < 2) return {name, 0, kNaN, "too few samples"};
  const double r = moments.correlation(), z = r * std::sqrt(moments.n);
  return {name, z, normalTwoSidedP(z), format("r = %.5f, z = r sqrt(n) = %.2f", r, z)};
}

}  // namespace

void Comoments::join(const Comoments& other) {
  if (other.n == 0) return;
  const double total = n + other.n, da = other.meanA - meanA, db = other.meanB - meanB;
  const double weight = n * other.n / total;
  m2A += other.m2A + da * da * weight;
  m2B += other.m2B + db * db * weight;
  coAB += other.coAB + da * db * weight;
  meanA += da * other.n / total;
  meanB += db * other.n / total;
  n = total;
}

double Comoments::correlation() const {
  if (!(m2A > 0) || !(m2B > 0)) return 1.0;
  return std::clamp(coAB / std::sqrt(m2A * m2B), -1.0, 1.0);
}

int patternFromName(const std::string& name) {
  for (size_t i = 0; i < kPatternNames.size(); ++i)
    if (name == kPatternNames[i]) return int(i);
  return -1;
}

std::string patternList() {
  std::string list;
  for (const char* name : kPatternNames) list += (list.empty() ? "" : ", ") + std::string(name);
  return list;
}

Verdict dieharderVerdict(double p) {
  if (std::isnan(p)) return Verdict::NotApplicable;
  if (p < 1e-6 || p > 1 - 1e-6) return Verdict::Failed;
  if (p < 0.005 || p > 0.995) return Verdict::Weak;
  return Verdict::Passed;
}

const char* verdictName(Verdict verdict) {
  switch (verdict) {
    case Verdict::Passed: return "PASSED";
    case Verdict::Weak: return "WEAK";
    case Verdict::Failed: return "FAILED";
    case Verdict::NotApplicable: break;
  }
  return "n/a";
}

bool thesisPass(double p) { return p >= 0.01 && p <= 0.99; }

// GSL's regularized upper incomplete gamma Q(dof/2, chi2/2), the chi-square upper tail
// (gsl_cdf_chisq_Q is the same function, but reports an underflow through GSL's error
// handler, which aborts by default: a failing hash gives chi-squares far in the tail, whose
// p-value is 0, not an error).
double chiSquareUpperP(double chiSquare, double dof) {
  if (!(dof > 0) || std::isnan(chiSquare)) return kNaN;
  if (chiSquare <= 0) return 1.0;
  gsl_sf_result q;
  gsl_error_handler_t* previous = gsl_set_error_handler_off();
  const int status = gsl_sf_gamma_inc_Q_e(dof / 2, chiSquare / 2, &q);
  gsl_set_error_handler(previous);
  if (status == GSL_EUNDRFLW) return 0.0;
  return status == GSL_SUCCESS ? std::clamp(q.val, 0.0, 1.0) : kNaN;
}

double normalTwoSidedP(double z) {
  if (std::isnan(z)) return kNaN;
  return std::min(1.0, 2 * gsl_cdf_ugaussian_Q(std::abs(z)));
}

double ksUniformP(std::vector<double> values, double* statistic) {
  std::sort(values.begin(), values.end());
  const double n = double(values.size());
  double d = 0;
  for (size_t i = 0; i < values.size(); ++i)
    d = std::max({d, (i + 1) / n - values[i], values[i] - i / n});
  if (statistic) *statistic = d;
  // Kolmogorov's limiting distribution Q(lambda) = 2 sum_j (-1)^(j-1) exp(-2 j^2 lambda^2),
  // with Stephens's small-sample correction of lambda (Stephens 1970; Numerical Recipes
  // §14.3). Written here because neither Debian 12 library has it: GSL has no KS
  // distribution, and Boost.Math's kolmogorov_smirnov.hpp arrived in Boost 1.75 (Debian 12
  // ships 1.74). The series converges fast for lambda >= 0.2; below, Q is 1 to double
  // precision (docs/decisions/042-distributions-from-gsl.md).
  const double lambda = (std::sqrt(n) + 0.12 + 0.11 / std::sqrt(n)) * d;
  if (lambda < 0.2) return 1.0;
  double sum = 0, sign = 1;
  for (int j = 1; j <= 100; ++j, sign = -sign) {
    const double term = sign * std::exp(-2.0 * j * j * lambda * lambda);
    sum += term;
    if (std::abs(term) < 1e-12) break;
  }
  return std::clamp(2 * sum, 0.0, 1.0);
}

bool fipsMonobitPasses(std::uint32_t ones) { return ones > 9725 && ones < 10275; }

bool fipsPokerPasses(const std::uint32_t* f) {
  double sumSquares = 0;
  for (int k = 0; k < 16; ++k) sumSquares += double(f[k]) * f[k];
  const double x = 16.0 / 5000.0 * sumSquares - 5000.0;
  return x > 2.16 && x < 46.17;
}

bool fipsRunsPass(const std::uint32_t* runs, std::uint32_t longestRun) {
  // FIPS 140-2 (change notice 1) intervals for runs of length 1, 2, 3, 4, 5, 6+, each bit.
  static const std::uint32_t low[6] = {2315, 1114, 527, 240, 103, 103};
  static const std::uint32_t high[6] = {2685, 1386, 723, 384, 209, 209};
  for (int bit = 0; bit < 2; ++bit)
    for (int k = 0; k < 6; ++k)
      if (runs[bit * 6 + k] < low[k] || runs[bit * 6 + k] > high[k]) return false;
  return longestRun < 26;
}

Result analyze(const Raw& raw) {
  Result result;
  const double n = double(raw.samples);
  const std::uint32_t* counts = raw.counts.data();

  // 1. 1D uniformity: chi-square of the 1024 buckets.
  {
    const double expected = n / HASH_STATS_BUCKETS;
    double chi = 0;
    for (int k = 0; k < HASH_STATS_BUCKETS; ++k) chi += std::pow(counts[k] - expected, 2) / expected;
    const double dof = HASH_STATS_BUCKETS - 1;
    result.tests.push_back({"uniformity", chi, chiSquareUpperP(chi, dof),
                            format("chi2 = %.1f, %.0f dof", chi, dof)});
  }
  // 2. 2D pairs (x, y): chi-square of the 64 x 64 cells, 4095 dof.
  {
    const int cells = HASH_STATS_PAIR_SIDE * HASH_STATS_PAIR_SIDE;
    const double expected = n / cells;
    double chi = 0;
    result.pairs.resize(cells);
    for (int k = 0; k < cells; ++k) {
      const double count = counts[HASH_STATS_COUNT_PAIRS + k];
      chi += std::pow(count - expected, 2) / expected;
      result.pairs[k] = count / expected;
    }
    result.tests.push_back({"pairs_2d", chi, chiSquareUpperP(chi, cells - 1),
                            format("chi2 = %.1f, %.0f dof", chi, cells - 1)});
  }
  // 3. Per-bit bias: a monobit z-score per bit of x; their squares sum to chi-square(32).
  {
    double chi = 0;
    int worst = 0;
    for (int b = 0; b < 32; ++b) {
      result.bitZ[b] = (counts[HASH_STATS_COUNT_BITS + b] - n / 2) / std::sqrt(n / 4);
      chi += result.bitZ[b] * result.bitZ[b];
      if (std::abs(result.bitZ[b]) > std::abs(result.bitZ[worst])) worst = b;
    }
    result.tests.push_back({"bit_bias", chi, chiSquareUpperP(chi, 32),
                            format("chi2 = %.1f, 32 dof; worst bit %.0f, z = %.2f", chi, worst,
                                   result.bitZ[worst])});
  }
  // 4. Serial correlations of u = x / 2^32: next sample, right-hand pixel, next frame.
  result.tests.push_back(correlationTest("serial_next", raw.next));
  result.tests.push_back(correlationTest("serial_right", raw.right));
  result.tests.push_back(correlationTest("serial_frame", raw.frame));
  // 5. Avalanche: each flip count is Binomial(A_i, 1/2) for an ideal hash (A_i inputs with
  // input bit i clear); the squared z-scores of the 1024 counts sum to chi-square(1024). The
  // bias score is the RMS of c_ij - 1/2, beside the RMS an ideal hash shows from sampling
  // alone, sqrt(mean 1/(4 A_i)).
  if (raw.avalancheInputs > 0) {
    double chi = 0, squares = 0, noise = 0;
    int rows = 0;
    result.avalanche.assign(32 * 32, 0.0);
    for (int i = 0; i < 32; ++i) {
      const double a = raw.flips[HASH_STATS_FLIPS_INPUTS + i];
      if (a == 0) continue;  // no input has this bit clear
      ++rows;
      noise += 1 / (4 * a);
      for (int j = 0; j < 32; ++j) {
        const int k = i * 32 + j;
        result.avalanche[k] = raw.flips[k] / a;
        chi += std::pow(raw.flips[k] - a / 2, 2) / (a / 4);
        squares += std::pow(result.avalanche[k] - 0.5, 2);
      }
    }
    result.avalancheBias = rows ? std::sqrt(squares / (32.0 * rows)) : 0;
    result.avalancheNoise = rows ? std::sqrt(noise / rows) : 0;
    result.tests.push_back({"avalanche", chi, chiSquareUpperP(chi, 32.0 * rows),
                            format("bias %.4f vs noise floor %.4f; ", result.avalancheBias,
                                   result.avalancheNoise) +
                                format("chi2 = %.0f, %.0f dof", chi, 32.0 * rows)});
  } else {
    result.tests.push_back({"avalanche", 0, kNaN, "needs the hash function, not a stream"});
  }
  // 6. FIPS 140-2 on 20,000-bit blocks: the count of blocks outside FIPS's intervals, and a
  // p-value over all blocks (monobit: sum of squared z; poker: the blocks' chi-squares add;
  // runs: the number of runs is 1 + Binomial(19999, 1/2) transitions).
  const size_t blocks = raw.fipsBlocks.size() / HASH_STATS_FIPS_STRIDE;
  if (blocks == 0) {
    for (const char* name : {"fips_monobit", "fips_poker", "fips_runs"})
      result.tests.push_back({name, 0, kNaN, "fewer than 20,000 bits"});
    return result;
  }
  double monobitChi = 0, pokerChi = 0, runsSum = 0;
  int monobitFails = 0, pokerFails = 0, runsFails = 0;
  for (size_t b = 0; b < blocks; ++b) {
    const std::uint32_t* block = raw.fipsBlocks.data() + b * HASH_STATS_FIPS_STRIDE;
    const double ones = block[HASH_STATS_FIPS_ONES];
    monobitChi += std::pow(ones - 10000, 2) / 5000;
    monobitFails += !fipsMonobitPasses(block[HASH_STATS_FIPS_ONES]);
    double sumSquares = 0;
    for (int k = 0; k < 16; ++k) sumSquares += std::pow(block[HASH_STATS_FIPS_POKER + k], 2);
    pokerChi += 16.0 / 5000.0 * sumSquares - 5000.0;
    pokerFails += !fipsPokerPasses(block + HASH_STATS_FIPS_POKER);
    runsSum += block[HASH_STATS_FIPS_TOTAL_RUNS] - 10000.5;
    runsFails += !fipsRunsPass(block + HASH_STATS_FIPS_RUNS, block[HASH_STATS_FIPS_LONGEST]);
  }
  const double nb = double(blocks);
  const char* failText = "%.0f of %.0f blocks fail FIPS; chi2 = %.1f over all";
  result.tests.push_back({"fips_monobit", monobitChi, chiSquareUpperP(monobitChi, nb),
                          format(failText, monobitFails, nb, monobitChi), monobitFails});
  result.tests.push_back({"fips_poker", pokerChi, chiSquareUpperP(pokerChi, 15 * nb),
                          format(failText, pokerFails, nb, pokerChi), pokerFails});
  const double runsZ = runsSum / std::sqrt(nb * 4999.75);
  result.tests.push_back({"fips_runs", runsZ, normalTwoSidedP(runsZ),
                          format("%.0f of %.0f blocks fail FIPS; runs z = %.2f", runsFails, nb,
                                 runsZ),
                          runsFails});
  return result;
}

KeyedResult combineKeys(std::vector<Result> perKey) {
  KeyedResult keyed;
  const size_t tests = perKey.empty() ? 0 : perKey[0].tests.size();
  keyed.ksP.assign(tests, kNaN);
  keyed.ksD.assign(tests, kNaN);
  if (perKey.size() >= 2)
    for (size_t t = 0; t < tests; ++t) {
      std::vector<double> ps;
      for (const Result& result : perKey) ps.push_back(result.tests[t].p);
      if (std::any_of(ps.begin(), ps.end(), [](double p) { return std::isnan(p); })) continue;
      keyed.ksP[t] = ksUniformP(ps, &keyed.ksD[t]);
    }
  keyed.perKey = std::move(perKey);
  return keyed;
}

}  // namespace hashstats
