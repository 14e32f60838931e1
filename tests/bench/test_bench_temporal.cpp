// `penumbra bench-temporal` (docs/decisions/120-temporal-stability.md): a tiny run on a static
// scene writes one row per side and key; a deterministic method under a fixed key changes by
// exactly 0 (no ratio: the reference never changed), Monte Carlo under a per-frame key by more;
// on the slowly moving plate the reference changes and the ratio is defined. Bad input exits
// 2 and writes nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "support/command.h"
#include "support/temp_directory.h"

namespace {

std::string readText(const std::filesystem::path& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

// The cells of the table row starting with "| label | key |".
std::vector<std::string> row(const std::string& table, const std::string& label, const std::string& key) {
  const size_t at = table.find("| " + label + " | " + key + " |");
  if (at == std::string::npos) return {};
  std::vector<std::string> cells;
  std::stringstream line(table.substr(at + 1, table.find('\n', at) - at - 1));
  for (std::string cell; std::getline(line, cell, '|');) {
    while (!cell.empty() && cell.front() == ' ') cell.erase(cell.begin());
    while (!cell.empty() && cell.back() == ' ') cell.pop_back();
    cells.push_back(cell);
  }
  return cells;
}

}  // namespace

TEST(BenchTemporal, StaticSceneZeroForFixedKeyPositiveForMonteCarloPerFrame) {
  const TempDirectory scratch("penumbra_bench_temporal");
  const std::filesystem::path out = scratch.path() / "temporal.md";
  setenv("PENUMBRA_CACHE", (scratch.path() / "cache").c_str(), 1);
  const CommandResult result = runPenumbra(
      "bench-temporal --scene cube --width 48 --height 32 --time-range 0:0.125 --fps 24 "
      "--keys fixed,per_frame --reference-samples 4 --set light.resolution=256 --side hard_shadow "
      "--side trace --out " + out.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const std::string table = readText(out);
  // Columns: side, key, map, pairs, mean change, worst change, worst pixel change, reference
  // change, ratio, error.
  const auto hardFixed = row(table, "hard_shadow, key fixed", "fixed");
  ASSERT_EQ(hardFixed.size(), 10u) << table;
  EXPECT_EQ(hardFixed[2], "256");
  EXPECT_EQ(hardFixed[3], "3") << "4 frames: 3 pairs";
  EXPECT_EQ(hardFixed[4], "0.000000");
  EXPECT_EQ(hardFixed[5], "0.000000");
  EXPECT_EQ(hardFixed[6], "0.0000");
  EXPECT_EQ(hardFixed[7], "0.000000") << "a static scene: the reference never changes";
  EXPECT_EQ(hardFixed[8], "-") << "no ratio without the reference's change";
  const auto traceFixed = row(table, "trace, key fixed", "fixed");
  ASSERT_EQ(traceFixed.size(), 10u) << table;
  EXPECT_EQ(traceFixed[4], "0.000000") << "the same key draws the same light samples";
  const auto tracePerFrame = row(table, "trace, key per frame", "per frame");
  ASSERT_EQ(tracePerFrame.size(), 10u) << table;
  EXPECT_GT(std::stod(tracePerFrame[4]), 0.0) << table;
  EXPECT_GT(std::stod(tracePerFrame[5]), 0.0) << table;
  EXPECT_GT(std::stod(tracePerFrame[6]), 1.0 / 64) << "one of at most 8 x 8 rays changing moves a pixel by 1/64";
  // The CSV: a header and 3 pairs for each of the 4 rows.
  const std::string csv = readText(scratch.path() / "temporal.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 4 * 3) << csv;
  unsetenv("PENUMBRA_CACHE");
}

TEST(BenchTemporal, MovingOccluderChangesTheReferenceAndDefinesTheRatio) {
  const TempDirectory scratch("penumbra_bench_temporal_moving");
  const std::filesystem::path out = scratch.path() / "temporal.md";
  setenv("PENUMBRA_CACHE", (scratch.path() / "cache").c_str(), 1);
  // Two frames a second apart: the plate has moved 0.0625.
  const CommandResult result = runPenumbra(
      "bench-temporal --scene slow_slide --width 48 --height 32 --time-range 0:1 --fps 1 "
      "--reference-samples 4 --side 'coarse=ssm:ssm.resolution=128' --out " + out.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const auto cells = row(readText(out), "coarse", "fixed");
  ASSERT_EQ(cells.size(), 10u) << readText(out);
  EXPECT_GT(std::stod(cells[7]), 0.0) << "the reference's shadow moved";
  EXPECT_NE(cells[8], "-");
  unsetenv("PENUMBRA_CACHE");
}

TEST(BenchTemporal, BadInputIsRefusedAndWritesNothing) {
  const TempDirectory scratch("penumbra_bench_temporal_refused");
  const std::string never = (scratch.path() / "never.md").string();
  for (const char* arguments :
       {"--time-range 2:1", "--time-range 0:0", "--time-range x", "--fps 0", "--keys sometimes",
        "--side no_such_method", "--side trace:trace.nope=1", "--side raster4d", "--scene no_such_scene"}) {
    const CommandResult result = runPenumbra(std::string("bench-temporal --width 32 --height 24 ") + arguments +
                                             " --out " + never);
    EXPECT_EQ(result.exitCode, 2) << arguments << "\n" << result.output;
    EXPECT_FALSE(std::filesystem::exists(never)) << arguments;
  }
}
