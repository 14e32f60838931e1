// `penumbra bench-compare` (docs/design.md#bench): a tiny run writes one row per side with the
// stages, counters, fetches per searched ray and error columns; bad input exits 2 naming it.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/command.h"
#include "support/temp_directory.h"

TEST(BenchCompare, TinyRunWritesOneRowPerSideWithRatiosAgainstTheFirst) {
  const TempDirectory scratch("penumbra_bench_compare");
  const std::string out = (scratch.path() / "compare.md").string();
  const auto cache = scratch.path() / "cache";
  setenv("PENUMBRA_CACHE", cache.c_str(), 1);  // the reference's disk cache, inherited
  const CommandResult result = runPenumbra(
      "bench-compare --scene cube --width 48 --height 32 --frames 1 --warmup 0 --out " + out +
      " --set light.resolution=128 --side 'every pixel:filter.skip_uniform=false' --side "
      "'tiles:filter.skip_uniform=true' --requested filter.visibility --counters filter.pixels "
      "--error-of filter");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  std::ifstream file(out);
  std::stringstream text;
  text << file.rdbuf();
  const std::string table = text.str();
  for (const char* expected : {"| every pixel | filter.skip_uniform=false |",
                               "| tiles | filter.skip_uniform=true |", "filter ms", "filter ratio",
                               "filter.pixels", "fetches / searched ray", "filter RMSE"})
    EXPECT_NE(table.find(expected), std::string::npos) << expected << "\n" << table;
  EXPECT_NE(table.find("| 1536 |"), std::string::npos) << "48 x 32 pixels filtered\n" << table;
}

TEST(BenchCompare, BadSetsAndMissingSidesAreRefused) {
  const TempDirectory scratch("penumbra_bench_compare_refused");
  const std::string never = (scratch.path() / "never.md").string();
  CommandResult result = runPenumbra("bench-compare --side 'x:trace.nope=1' --out " + never);
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_NE(result.output.find("nope"), std::string::npos) << result.output;
  result = runPenumbra("bench-compare --out " + never);
  EXPECT_EQ(result.exitCode, 2) << result.output;
  result = runPenumbra("bench-compare --scene no_such_scene --side a --out " + never);
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_FALSE(std::filesystem::exists(never)) << "a refused run wrote " << never;
}
