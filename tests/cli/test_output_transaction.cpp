// The directory transaction itself (docs/reliability.md; app/io/output_path.h): the target holds
// the old contents or the new, never both; nothing temporary is left after a failure.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <fstream>

#include "base/input_error.h"
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

// A directory that became someone else's while the run worked is not replaced at commit.
TEST(OutputTransaction, CommitChecksTheTargetAgainstTheManifest) {
  const TempDirectory dir("penumbra_transaction_manifest");
  const fs::path target = dir.path() / "bench";
  DirectoryTransaction bench(target, "results.json");
  writeTextFile(bench.path() / "results.csv", "a");
  writeTextFile(bench.path() / "results.json", "b");
  fs::create_directories(target);
  writeTextFile(target / "stages.md", "someone else's");
  EXPECT_THROW(bench.commit(), InputError);
  EXPECT_EQ(entries(target), 1u);
  EXPECT_TRUE(fs::exists(target / "stages.md"));
}

// Killed runs leave `.NAME.partial-PID` (directories) and `.stem.partial-PID.ext` (files);
// the next check of the same output removes those whose process is gone, not live ones.
TEST(OutputTransaction, LeftoversOfDeadRunsAreRemovedAtTheNextCheck) {
  const TempDirectory dir("penumbra_transaction_leftovers");
  fs::create_directories(dir.path() / ".out.partial-999999999" / "inner");
  fs::create_directories(dir.path() / (".out.partial-" + std::to_string(::getppid())));  // alive
  dir.write(".t.partial-999999999.json", "x");
  checkOutputDirectory(dir.path() / "out", "--out", "run.json");
  checkOutputFile(dir.path() / "t.json", "--out");
  EXPECT_FALSE(fs::exists(dir.path() / ".out.partial-999999999"));
  EXPECT_FALSE(fs::exists(dir.path() / ".t.partial-999999999.json"));
  EXPECT_TRUE(fs::exists(dir.path() / (".out.partial-" + std::to_string(::getppid()))));
}

// A failed write names the OS reason: a full file system (a 64 KiB tmpfs, where root may
// mount one), for a text file and for an EXR (whose library says only "Failed OpenEXR write").
TEST(OutputTransaction, AFailedWriteNamesTheReason) {
  const TempDirectory dir("penumbra_transaction_full");
  const fs::path mount = dir.path() / "small";
  fs::create_directories(mount);
  if (std::system(("mount -t tmpfs -o size=64k tmpfs " + mount.string() + " 2>/dev/null").c_str()) != 0)
    GTEST_SKIP() << "cannot mount a tmpfs here (not root)";
  std::string message;
  try {
    writeTextFile(mount / "big.txt", std::string(1 << 20, 'x'));
  } catch (const std::exception& error) {
    message = error.what();
  }
  try {
    std::vector<float> noise(256 * 256 * 4);  // incompressible: 1 MiB of EXR
    std::uint32_t state = 1;
    for (float& value : noise) value = float((state = state * 1664525u + 1013904223u) >> 8);
    writeExr(mount / "big.exr", noise, 256, 256, {"R", "G", "B", "A"});
  } catch (const std::exception& error) {
    message += std::string("\n") + error.what();
  }
  const bool leftover = !fs::is_empty(mount);
  (void)std::system(("umount " + mount.string()).c_str());
  size_t count = 0;
  for (size_t at = 0; (at = message.find("No space left on device", at)) != std::string::npos; ++at) ++count;
  EXPECT_EQ(count, 2u) << message;
  EXPECT_FALSE(leftover) << "a partial file left on the full file system";
}

TEST(OutputTransaction, OutputChecksNameTheProblem) {
  const TempDirectory dir("penumbra_output_checks");
  const std::string file = dir.write("file", "x");
  EXPECT_THROW(checkOutputFile(fs::path(file) / "a.md", "--out"), InputError);
  EXPECT_THROW(checkOutputFile(dir.path(), "--out"), InputError);  // a directory
  EXPECT_THROW(checkOutputDirectory(file, "--out", "run.json"), InputError);
  EXPECT_THROW(checkOutputDirectory(dir.path(), "--out", "run.json"), InputError);  // foreign
  EXPECT_NO_THROW(checkOutputDirectory(dir.path(), "--out", ""));  // files are added one by one
  EXPECT_NO_THROW(checkOutputDirectory(dir.path() / "new" / "deeper", "--out", "run.json"));
  EXPECT_NO_THROW(checkOutputFile(dir.path() / "new" / "t.json", "--out"));
}
