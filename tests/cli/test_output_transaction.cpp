// The directory transaction itself (docs/reliability.md; app/io/output_path.h): the target holds
// the old contents or the new, never both; nothing temporary is left after a failure.
#include <gtest/gtest.h>

#include <fstream>

#include "core/input_error.h"
#include "io/image_export.h"
#include "io/output_path.h"
#include "support/scene_writer.h"

namespace fs = std::filesystem;

namespace {
size_t entries(const fs::path& directory) {
  return size_t(std::distance(fs::directory_iterator(directory), fs::directory_iterator()));
}
}  // namespace

TEST(OutputTransaction, FailureKeepsThePreviousContentsAndLeavesNothing) {
  const TempDirectory dir("penumbra_transaction");
  const fs::path target = dir.path() / "export";
  {
    DirectoryTransaction first(target);
    writeTextFile(first.path() / "run.json", "old");
    writeTextFile(first.path() / "old_only.txt", "old");
    first.commit();
  }
  EXPECT_EQ(entries(dir.path()), 1u);  // the target alone
  try {
    DirectoryTransaction failing(target);
    writeTextFile(failing.path() / "run.json", "new");
    throw std::runtime_error("rendering failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(entries(dir.path()), 1u) << "temporary left behind";
  std::ifstream kept(target / "run.json");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(kept), {}), "old");
  {
    DirectoryTransaction second(target);
    writeTextFile(second.path() / "run.json", "new");
    second.commit();
  }
  EXPECT_FALSE(fs::exists(target / "old_only.txt")) << "old and new side by side";
  EXPECT_EQ(entries(target), 1u);
  EXPECT_EQ(entries(dir.path()), 1u);
}

TEST(OutputTransaction, MergingCommitKeepsOtherFilesAndWritesTheReportLast) {
  const TempDirectory dir("penumbra_transaction_merge");
  dir.write("stages.md", "someone else's");
  DirectoryTransaction bench(dir.path());
  writeTextFile(bench.path() / "results.csv", "a");
  writeTextFile(bench.path() / "results.md", "b");
  bench.commitFiles("results.md");
  EXPECT_TRUE(fs::exists(dir.path() / "stages.md"));
  EXPECT_TRUE(fs::exists(dir.path() / "results.csv"));
  EXPECT_TRUE(fs::exists(dir.path() / "results.md"));
  EXPECT_EQ(entries(dir.path()), 3u);
}

TEST(OutputTransaction, OutputChecksNameTheProblem) {
  const TempDirectory dir("penumbra_output_checks");
  const std::string file = dir.write("file", "x");
  EXPECT_THROW(checkOutputFile(fs::path(file) / "a.md", "--out"), InputError);
  EXPECT_THROW(checkOutputFile(dir.path(), "--out"), InputError);  // a directory
  EXPECT_THROW(checkOutputDirectory(file, "--out", "run.json"), InputError);
  EXPECT_THROW(checkOutputDirectory(dir.path(), "--out", "run.json"), InputError);  // foreign
  EXPECT_NO_THROW(checkOutputDirectory(dir.path(), "--out", ""));  // files are merged
  EXPECT_NO_THROW(checkOutputDirectory(dir.path() / "new" / "deeper", "--out", "run.json"));
  EXPECT_NO_THROW(checkOutputFile(dir.path() / "new" / "t.json", "--out"));
}
