// `penumbra hash-stats` (docs/hash_stats.md): the table, JSON and images it promises, bad flags
// exit 2 naming the valid values, and the dieharder runner: parsing, a real run, cancel.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "gl/hash_kind.h"
#include "stats/dieharder_run.h"
#include "support/command.h"
#include "support/temp_directory.h"

namespace fs = std::filesystem;

TEST(HashStatsCli, WritesTablesJsonAndImagesForEveryHash) {
  const TempDirectory scratch("penumbra_hash_stats_cli");
  const fs::path out = scratch.path() / "out";
  const auto result = runPenumbra("hash-stats --count 4096 --keys 2 --out " + out.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  std::ifstream in(out / "hash_stats.json");
  const auto json = nlohmann::json::parse(in);
  ASSERT_EQ(json["results"].size(), kHashKindNames.size());
  for (const auto& row : json["results"]) {
    const std::string stem = row["hash"].get<std::string>() + "_linear_";
    for (const char* image : {"pairs", "avalanche", "bits", "verdicts"}) {
      EXPECT_GT(fs::file_size(out / (stem + image + ".png")), 100u) << stem << image;
      EXPECT_TRUE(fs::exists(out / (stem + image + ".exr"))) << stem << image;
    }
    EXPECT_EQ(row["tests"].size(), 10u);
    EXPECT_GT(row["hashes_per_second"].get<double>(), 0.0);
    for (const auto& test : row["tests"]) EXPECT_EQ(test["p_per_key"].size(), 2u);
    // The printed table has a row per hash.
    EXPECT_NE(result.output.find("| " + row["hash"].get<std::string>() + " | linear |"),
              std::string::npos);
  }
  // md5_4 fails everything on the linear seeds, even at 4096 samples.
  for (const auto& row : json["results"]) {
    if (row["hash"] != "md5_4") continue;
    for (const auto& test : row["tests"]) EXPECT_EQ(test["verdict"], "FAILED") << test["name"];
  }
  EXPECT_TRUE(fs::exists(out / "hash_stats.md"));
}

TEST(HashStatsCli, BadFlagsExitTwoNamingTheValidValues) {
  auto bad = runPenumbra("hash-stats --hash sha1");
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.output.find("xxhash32"), std::string::npos) << bad.output;
  bad = runPenumbra("hash-stats --pattern spiral");
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.output.find("morton"), std::string::npos) << bad.output;
  bad = runPenumbra("hash-stats --count 100");
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.output.find("--count"), std::string::npos) << bad.output;
  bad = runPenumbra("hash-stats --count 33554432");
  EXPECT_EQ(bad.exitCode, 2);
  bad = runPenumbra("hash-stats --keys 0");
  EXPECT_EQ(bad.exitCode, 2);
}

TEST(Dieharder, ParsesResultLinesOnly) {
  const std::string text =
      "#=============================================================================#\n"
      "#            dieharder version 3.31.1 Copyright 2003 Robert G. Brown          #\n"
      "   rng_name    |rands/second|   Seed   |\n"
      "stdin_input_raw|  2.13e+07  |1234567890|\n"
      "        test_name   |ntup| tsamples |psamples|  p-value |Assessment\n"
      "   diehard_birthdays|   0|       100|     100|0.47224747|  PASSED  \n"
      "        diehard_runs|   0|    100000|     100|0.00412345|   WEAK   \n"
      "        diehard_runs|   0|    100000|     100|0.00000000|  FAILED  \n";
  const auto lines = parseDieharderOutput(text);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0].test, "diehard_birthdays");
  EXPECT_DOUBLE_EQ(lines[0].p, 0.47224747);
  EXPECT_EQ(lines[0].assessment, "PASSED");
  EXPECT_EQ(lines[1].assessment, "WEAK");
  EXPECT_EQ(lines[2].p, 0.0);
  EXPECT_EQ(diehardTests().size(), 16u);
  EXPECT_EQ(thesisDiehardPasses("md5_16"), 11);
}

// A real run of one DIEHARD test (birthdays, about 4 s), and cancel ending a long one.
TEST(Dieharder, RunsOneTestAndCancels) {
  if (findDieharder().empty()) GTEST_SKIP() << "dieharder not installed";
  DieharderRun run(penumbraBinary(), "md5_16", {0});
  run.start();
  while (!run.finished()) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_EQ(run.error(), "");
  ASSERT_EQ(run.lines().size(), 1u);
  EXPECT_EQ(run.lines()[0].test, "diehard_birthdays");
  EXPECT_EQ(run.testsDone(), 1);

  DieharderRun longRun(penumbraBinary(), "md5_64", diehardTests());
  longRun.start();
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  const auto start = std::chrono::steady_clock::now();
  longRun.cancel();
  while (!longRun.finished()) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
  EXPECT_TRUE(longRun.cancelled());
  EXPECT_LT(longRun.testsDone(), 16);
}

// hash-stats --out under a file, a foreign directory, or a directory no one may create files
// in (/proc, even as root) exited 1 after all the GPU work; now 2, before it.
TEST(HashStatsCli, BadOutExitsTwoBeforeAnyWork) {
  const TempDirectory scratch("penumbra-hash-stats-out");
  const std::string file = scratch.write("afile", "x");
  scratch.write("notes.txt", "mine");
  for (const std::string& out : {file, file + "/sub", scratch.path().string(), std::string("/proc/penumbra_x")}) {
    const auto result = runPenumbra("hash-stats --hash md5_16 --pattern linear --count 1024 --out " + out);
    EXPECT_EQ(result.exitCode, 2) << out << "\n" << result.output;
    EXPECT_NE(result.output.find("--out"), std::string::npos) << result.output;
    EXPECT_EQ(result.output.find("| md5_16"), std::string::npos) << "worked before checking: " << result.output;
  }
  std::ifstream kept(scratch.path() / "notes.txt");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(kept), {}), "mine");
}
