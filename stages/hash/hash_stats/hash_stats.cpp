// Stage `hash_stats`: is the hash random enough? (thesis §3.1, §4.3, Appendix A; Jarzynski &
// Olano 2020 test each hash on several input patterns.) DIEHARD-like statistics of the
// chosen hash over N inputs of the chosen pattern, computed on the GPU and finished in
// double on the CPU (app/stats/), shown as pictures: the 2D pair histogram (lattices and
// stripes show at a glance), the avalanche matrix, per-bit bias bars and the verdicts.
// `penumbra hash-stats` prints the same numbers as a table.
//   1. Recompute only when a parameter changes (the statistics do not depend on the scene
//      or the frame key; the default 2^20 samples take a fraction of a second on llvmpipe).
//   2. Upload the four pictures; the p-values go to the counters for the inspector.
#include <cmath>
#include <optional>

#include "core/frame.h"
#include "gl/hash_kind.h"
#include "stats/hash_stats_gpu.h"
#include "stats/hash_stats_views.h"

namespace {

class HashStatsStage final : public Stage {
public:
  HashStatsStage() {
    outputs_ = {
        {"pairs",
         "2D uniformity: the light samples (u, v) = (word x, word y) of N inputs binned 64 x 64 "
         "(u right, v up), each cell's count / expected count (1 = uniform, colour scale 0..2). "
         "A good hash is even noise; LCGs draw lattices, cut-down MD5 draws stripes.",
         GL_R32F, {"pairs"}, {0, 0, 2, Colormap::Perceptual}},
        {"avalanche",
         "Avalanche matrix: row i (top = input bit 0 of seed.x), column j (output bit j of word "
         "x): how often setting input bit i flips output bit j. Ideal 0.5 everywhere (white); "
         "red = always flips, blue = never. The identity would show a red diagonal.",
         GL_R32F, {"flip_probability"}, {0, 0, 1, Colormap::Diverging}},
        {"bit_bias",
         "Per-bit bias of word x: one bar per bit (bit 0 left), up (red) when the bit is 1 too "
         "often, down (blue) when too rarely; height = monobit z-score, full at |z| = 8. |z| > 3 "
         "is rare (0.3%) for a fair bit.",
         GL_R32F, {"z"}, {0, -8, 8, Colormap::Diverging}},
        {"verdicts",
         "The table as colours: rows = the tests (top: uniformity, pairs_2d, bit_bias, "
         "serial_next, serial_right, serial_frame, avalanche, fips_monobit, fips_poker, "
         "fips_runs), columns = keys, 16 x 16 texels each. White PASSED, pink WEAK, red "
         "FAILED (dieharder's rule), "
         "blue not applicable. The p-values are in the counters (inspector).",
         GL_R32F, {"verdict"}, {0, -1, 1, Colormap::Diverging}},
    };
    params_ = {
        Param::choice("hash",
                      "Hash to test (the trace's choices: md5_16 is the thesis's, md5_4 / md5_8 "
                      "the listing cut to 4 / 8 steps, lcg15 C rand(), lcg32 a 32-bit LCG, "
                      "xxhash32, pcg3d, md5_64).",
                      {kHashKindNames.begin(), kHashKindNames.end()}, int(HashKind::Md5_16)),
        Param::choice("pattern",
                      "Inputs: linear = seeds 1, 2, ..., N (what the thesis tested, §3.1); pixels "
                      "= the renderer's seeds (x, y, ray, 0) of a 1024-wide image; morton = "
                      "pixels in Z order; frames = pixel (0, 0), consecutive frame keys key * 2^24 + i.",
                      {hashstats::kPatternNames.begin(), hashstats::kPatternNames.end()},
                      HASH_PATTERN_LINEAR),
        Param::integer("count_log2", "N = 2^count_log2 samples per key (2^24 takes seconds).",
                       20, 10, 24),
        Param::integer("keys",
                       "Repeat over K keys (key, key + 1, ...): a single p-value says little; "
                       "with K >= 2 the counters give a Kolmogorov-Smirnov p of each test's K "
                       "p-values.",
                       1, 1, 16),
        Param::integer("key", "First key (the Appendix A key XORed into the seed).", 0, 0,
                       1000000),
    };
  }
  std::string name() const override { return "hash_stats"; }
  std::string summary() const override {
    return "DIEHARD-like statistics of the hash: pair histogram, avalanche, bit bias, "
           "serial correlation, FIPS 140-2, each with its p-value.";
  }
  std::string thesisSection() const override { return "thesis §3.1, §4.3, App. A"; }

  void run(Frame& frame) override {
    // 1. Recompute when a parameter changed.
    std::vector<double> values;
    for (const Param& p : params_) values.push_back(p.value);
    if (values != computedFor_) {
      keyed_ = gpu_.runKeys(param("hash").asInt(), param("pattern").asInt(),
                            std::uint64_t(1) << param("count_log2").asInt(), param("keys").asInt(),
                            std::uint32_t(param("key").asInt()));
      computedFor_ = values;
    }
    // 2. Pictures and counters.
    const hashstats::Result& first = keyed_.perKey[0];
    upload(frame, "pairs", pairsImage(first));
    upload(frame, "avalanche", avalancheImage(first));
    upload(frame, "bit_bias", bitBiasImage(first));
    upload(frame, "verdicts", verdictImage(keyed_));
    int passed = 0;
    for (size_t t = 0; t < first.tests.size(); ++t) {
      const hashstats::TestResult& test = first.tests[t];
      passed += test.verdict() == hashstats::Verdict::Passed;
      if (!std::isnan(test.p)) frame.counters["hash_stats." + test.name + ".p"] = test.p;
      if (!std::isnan(keyed_.ksP[t])) frame.counters["hash_stats." + test.name + ".ks_p"] = keyed_.ksP[t];
    }
    frame.counters["hash_stats.passed"] = passed;
    frame.counters["hash_stats.avalanche_bias"] = first.avalancheBias;
    frame.counters["hash_stats.avalanche_noise_floor"] = first.avalancheNoise;
  }

private:
  void upload(Frame& frame, const char* name, const StatsImage& image) {
    GlTexture& texture = frame.output(*this, name, image.width, image.height);
    glTextureSubImage2D(texture.id(), 0, 0, 0, image.width, image.height, GL_RED, GL_FLOAT,
                        image.values.data());
  }

  GpuHashStats gpu_;
  hashstats::KeyedResult keyed_;
  std::vector<double> computedFor_;
};

}  // namespace

std::unique_ptr<Stage> makeHashStatsStage() { return std::make_unique<HashStatsStage>(); }
