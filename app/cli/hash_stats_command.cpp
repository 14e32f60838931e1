#include "cli/hash_stats_command.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <thread>

#include "gl/gl_context.h"
#include "gl/hash_kind.h"
#include "io/image_export.h"
#include "io/output_path.h"
#include "stats/dieharder_run.h"
#include "stats/hash_stats_gpu.h"
#include "stats/hash_stats_views.h"

using namespace hashstats;

namespace {

struct Row {
  std::string hash, pattern;
  double hashesPerSecond = 0;
  KeyedResult keyed;
};

struct DieharderCount {
  std::string hash;
  int passed = 0, weak = 0, failed = 0, thesis = 0;  // thesis: p in [0.01, 0.99]
  std::vector<DieharderLine> lines;
};

std::string fixed(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

std::string pText(double p) {
  if (std::isnan(p)) return "n/a";
  std::string text = p < 1e-4 && p > 0 ? fixed("%.1e", p) : fixed("%.4f", p);
  const Verdict verdict = dieharderVerdict(p);
  if (verdict == Verdict::Weak) text += " weak";
  if (verdict == Verdict::Failed) text += " **FAIL**";
  return text;
}

// " text |" (appended piecewise: GCC 12 warns falsely on " " + std::string temporaries).
void appendCell(std::string& md, const std::string& text) {
  md += ' ';
  md += text;
  md += " |";
}

int passedCount(const Result& result) {
  int passed = 0;
  for (const TestResult& t : result.tests) passed += t.verdict() == Verdict::Passed;
  return passed;
}

// 1. The comparison table: one row per hash and pattern, one column per test (key 0's p),
// the counts of PASSED tests by dieharder's rule and by the thesis's, and the throughput.
std::string comparisonTable(const std::vector<Row>& rows, const HashStatsOptions& options) {
  std::string md = "| hash | pattern |";
  for (const char* name : kTestNames) md += std::string(" ") + name + " |";
  md += " passed | p in [0.01, 0.99] | M hashes/s |\n|---|---|";
  for (size_t t = 0; t < kTestNames.size(); ++t) md += "---|";
  md += "---|---|---|\n";
  for (const Row& row : rows) {
    const Result& first = row.keyed.perKey[0];
    int applicable = 0, thesis = 0;
    md += "| " + row.hash + " | " + row.pattern + " |";
    for (const TestResult& t : first.tests) {
      appendCell(md, pText(t.p));
      applicable += !std::isnan(t.p);
      thesis += thesisPass(t.p);
    }
    md += " " + std::to_string(passedCount(first)) + " of " + std::to_string(applicable) + " | " +
          std::to_string(thesis) + " of " + std::to_string(applicable) + " | " +
          fixed("%.1f", row.hashesPerSecond / 1e6) + " |\n";
  }
  if (options.keys > 1) {
    md += "\nKolmogorov-Smirnov p of each test's " + std::to_string(options.keys) +
          " p-values (keys " + std::to_string(options.key) + ".." +
          std::to_string(options.key + options.keys - 1) + "):\n\n| hash | pattern |";
    for (const char* name : kTestNames) md += std::string(" ") + name + " |";
    md += "\n|---|---|";
    for (size_t t = 0; t < kTestNames.size(); ++t) md += "---|";
    md += "\n";
    for (const Row& row : rows) {
      md += "| " + row.hash + " | " + row.pattern + " |";
      for (double p : row.keyed.ksP) appendCell(md, pText(p));
      md += "\n";
    }
  }
  return md;
}

// 2. One hash and pattern in detail: every test's statistic, p and both verdicts.
std::string detailTable(const Row& row) {
  std::string md = "### " + row.hash + ", pattern " + row.pattern + "\n\n"
                   "| test | statistic | p | dieharder | thesis [0.01, 0.99] |\n|---|---|---|---|---|\n";
  for (const TestResult& t : row.keyed.perKey[0].tests)
    md += "| " + t.name + " | " + t.detail + " | " + pText(t.p) + " | " + verdictName(t.verdict()) +
          " | " + (std::isnan(t.p) ? "n/a" : thesisPass(t.p) ? "pass" : "fail") + " |\n";
  return md;
}

std::string dieharderTable(const std::vector<DieharderCount>& counts) {
  std::string md =
      "| hash | PASSED | WEAK | FAILED | p in [0.01, 0.99] | thesis §3.1 (of 15 tests) |\n"
      "|---|---|---|---|---|---|\n";
  for (const DieharderCount& c : counts) {
    const int total = c.passed + c.weak + c.failed, thesis = thesisDiehardPasses(c.hash);
    md += "| " + c.hash + " | " + std::to_string(c.passed) + " | " + std::to_string(c.weak) +
          " | " + std::to_string(c.failed) + " | " + std::to_string(c.thesis) + " of " +
          std::to_string(total) + " | " + (thesis < 0 ? "-" : std::to_string(thesis)) + " |\n";
  }
  md += "\nUnder a perfect generator each p-value falls outside [0.01, 0.99] with probability "
        "0.02, so all 18 p-values of the DIEHARD set land inside only 0.98^18 = 70% of the "
        "time, and dieharder calls one of them WEAK in 1 - 0.99^18 = 17% of runs: a count "
        "that moves by one or two between keys says nothing about the hash. (With the same key "
        "the stream, and so every p-value, is the same: dieharder -g 200 reads the stream, it "
        "does not seed it; the thesis's counts came from its own stream.) A hash is bad when a "
        "test fails again and again (p ~ 0 on every key).\n";
  return md;
}

nlohmann::json toJson(const std::vector<Row>& rows, const std::vector<DieharderCount>& dieharder,
                      const HashStatsOptions& options, const std::string& renderer) {
  const auto number = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
  nlohmann::json json = {{"count", options.count}, {"keys", options.keys}, {"key", options.key},
                         {"renderer", renderer}, {"results", nlohmann::json::array()}};
  for (const Row& row : rows) {
    const Result& first = row.keyed.perKey[0];
    nlohmann::json tests = nlohmann::json::array();
    for (size_t t = 0; t < first.tests.size(); ++t) {
      const TestResult& test = first.tests[t];
      nlohmann::json perKey = nlohmann::json::array();
      for (const Result& result : row.keyed.perKey) perKey.push_back(number(result.tests[t].p));
      tests.push_back({{"name", test.name}, {"statistic", number(test.statistic)},
                       {"p", number(test.p)}, {"verdict", verdictName(test.verdict())},
                       {"thesis_pass", thesisPass(test.p)}, {"detail", test.detail},
                       {"failed_blocks", test.failedBlocks}, {"p_per_key", perKey},
                       {"ks_p", number(row.keyed.ksP[t])}});
    }
    json["results"].push_back({{"hash", row.hash}, {"pattern", row.pattern},
                               {"hashes_per_second", row.hashesPerSecond}, {"tests", tests},
                               {"avalanche_bias", first.avalancheBias},
                               {"avalanche_noise_floor", first.avalancheNoise},
                               {"bit_z", first.bitZ}});
  }
  for (const DieharderCount& c : dieharder) {
    nlohmann::json lines = nlohmann::json::array();
    for (const DieharderLine& line : c.lines)
      lines.push_back({{"test", line.test}, {"ntup", line.ntup}, {"p", line.p},
                       {"assessment", line.assessment}});
    json["dieharder"].push_back({{"hash", c.hash}, {"passed", c.passed}, {"weak", c.weak},
                                 {"failed", c.failed}, {"thesis_interval", c.thesis},
                                 {"thesis_claim", thesisDiehardPasses(c.hash)}, {"lines", lines}});
  }
  return json;
}

void writeImages(const std::filesystem::path& dir, const Row& row) {
  const std::string stem = row.hash + "_" + row.pattern + "_";
  const Result& first = row.keyed.perKey[0];
  const std::pair<const char*, StatsImage> images[] = {{"pairs", pairsImage(first)},
                                                       {"avalanche", avalancheImage(first)},
                                                       {"bits", bitBiasImage(first)},
                                                       {"verdicts", verdictImage(row.keyed)}};
  for (const auto& [name, image] : images) {
    const int scale = std::max(1, 256 / std::max(image.width, image.height));
    writePng(dir / (stem + name + ".png"), enlargedRgb(image, scale), image.width * scale,
             image.height * scale);
    writeExr(dir / (stem + name + ".exr"), image.values, image.width, image.height, {name});
  }
}

DieharderCount runDieharder(const std::string& hash, std::uint32_t key) {
  DieharderRun run("/proc/self/exe", hash, diehardTests(), key);
  run.start();
  for (int shown = -1; !run.finished(); std::this_thread::sleep_for(std::chrono::milliseconds(200)))
    if (run.testsDone() != shown) {
      shown = run.testsDone();
      std::fprintf(stderr, "penumbra hash-stats: dieharder %s: %d of %d tests\n", hash.c_str(),
                   shown, run.testsTotal());
    }
  if (!run.error().empty()) throw std::runtime_error(run.error());
  DieharderCount count;
  count.hash = hash;
  count.lines = run.lines();
  for (const DieharderLine& line : count.lines) {
    count.passed += line.assessment == "PASSED";
    count.weak += line.assessment == "WEAK";
    count.failed += line.assessment == "FAILED";
    count.thesis += thesisPass(line.p);
  }
  return count;
}

}  // namespace

std::string checkHashStatsOptions(const HashStatsOptions& options) {
  if (options.hash != "all" && !hashKindFromName(options.hash))
    return "unknown hash '" + options.hash + "'; valid: all, " + hashKindList();
  if (options.pattern != "all" && patternFromName(options.pattern) < 0)
    return "unknown pattern '" + options.pattern + "'; valid: all, " + patternList();
  if (options.count < 1024 || options.count > GpuHashStats::kMaxSamples)
    return "--count must be in [1024, 16777216] (2^10 .. 2^24), got " + std::to_string(options.count);
  if (options.keys < 1 || options.keys > 64)
    return "--keys must be in [1, 64], got " + std::to_string(options.keys);
  if (options.dieharder && findDieharder().empty())
    return "--dieharder needs the dieharder program (Debian package dieharder; scripts/setup.sh "
           "installs it)";
  return "";
}

int runHashStatsCommand(const HashStatsOptions& options) {
  if (const std::string problem = checkHashStatsOptions(options); !problem.empty()) {
    std::fprintf(stderr, "penumbra hash-stats: %s\n", problem.c_str());
    return 2;
  }
  // The output rule (io/output_path.h): checked before any GPU work; one transaction,
  // hash_stats.json (the manifest) last.
  if (!options.out.empty()) checkOutputDirectory(options.out, "--out", "hash_stats.json");
  std::unique_ptr<DirectoryTransaction> transaction;
  std::string error;
  auto context = GlContext::createHeadless(error);
  if (!context) {
    std::fprintf(stderr, "penumbra hash-stats: %s\n", error.c_str());
    return 1;
  }
  try {
    std::vector<std::string> hashes, patterns;
    if (options.hash == "all") hashes.assign(kHashKindNames.begin(), kHashKindNames.end());
    else hashes.push_back(options.hash);
    if (options.pattern == "all") patterns.assign(kPatternNames.begin(), kPatternNames.end());
    else patterns.push_back(options.pattern);
    if (!options.out.empty()) transaction = std::make_unique<DirectoryTransaction>(options.out, "hash_stats.json");
    const std::filesystem::path out = transaction ? transaction->path() : std::filesystem::path();

    // 1. Statistics and throughput on the GPU, per hash and pattern.
    GpuHashStats gpu;
    std::vector<Row> rows;
    for (const std::string& hash : hashes) {
      const int kind = int(*hashKindFromName(hash));
      const double speed = gpu.hashesPerSecond(kind, std::uint32_t(std::min<std::uint64_t>(options.count, 1u << 22)));
      for (const std::string& pattern : patterns) {
        std::fprintf(stderr, "penumbra hash-stats: %s, %s\n", hash.c_str(), pattern.c_str());
        rows.push_back({hash, pattern, speed,
                        gpu.runKeys(kind, patternFromName(pattern), options.count, options.keys, options.key)});
        if (transaction) writeImages(out, rows.back());
      }
    }
    // 2. The real battery, where asked.
    std::vector<DieharderCount> dieharder;
    if (options.dieharder)
      for (const std::string& hash : hashes) dieharder.push_back(runDieharder(hash, options.key));

    // 3. Tables.
    const std::string renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    std::string md = "# Hash statistics (penumbra hash-stats)\n\n" + std::to_string(options.count) +
                     " samples per key, " + std::to_string(options.keys) + " key(s) from " +
                     std::to_string(options.key) + "; " + renderer +
                     ". Cells: p-value of key " + std::to_string(options.key) +
                     " (weak / **FAIL** by dieharder's rule: outside [0.005, 0.995] / "
                     "[1e-6, 1 - 1e-6]).\n\n" + comparisonTable(rows, options);
    if (rows.size() == 1) md += "\n" + detailTable(rows[0]);
    if (!dieharder.empty())
      md += "\n## penumbra hash --key " + std::to_string(options.key) +
            " | dieharder -g 200, DIEHARD tests\n\n" + dieharderTable(dieharder);
    std::fputs(md.c_str(), stdout);
    if (transaction) {
      writeTextFile(out / "hash_stats.md", md);
      writeTextFile(out / "hash_stats.json", toJson(rows, dieharder, options, renderer).dump(1) + "\n");
      transaction->commit();
    }
    return 0;
  } catch (const std::exception& problem) {
    std::fprintf(stderr, "penumbra hash-stats: %s\n", problem.what());
    return 1;
  }
}
