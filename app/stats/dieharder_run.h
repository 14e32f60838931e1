// The real battery (thesis §3.1; docs/hash_stats.md): `penumbra hash --hash H | dieharder -g 200 -d
// N` for each DIEHARD test N, in a background thread, one child process group per test (so cancel
// ends exactly those processes), with the output parsed line by line. Used by `penumbra hash-stats
// --dieharder` and the window's hash_stats panel.
#pragma once
#include <atomic>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

// One result line of dieharder: "diehard_runs|   0|  100000|     100|0.43018869|  PASSED".
struct DieharderLine {
  std::string test;
  int ntup = 0;
  double p = 0;
  std::string assessment;  // PASSED, WEAK, FAILED
};

// The result lines of dieharder's output (header and comment lines skipped).
std::vector<DieharderLine> parseDieharderOutput(const std::string& text);

// The DIEHARD set of dieharder: tests 0..16 without 14 (diehard_sums, which dieharder marks
// "Do Not Use"): 16 tests, 18 p-values (runs and craps give two each).
std::vector<int> diehardTests();

// Where dieharder is on PATH, or "" when it is not installed.
std::string findDieharder();

// The thesis's counts (§3.1, "passed N of 15 DIEHARD tests"), for the table beside ours:
// md5_16 11, full MD5 12, C rand() 6; -1 for hashes the thesis did not test.
int thesisDiehardPasses(const std::string& hash);

class DieharderRun {
public:
  // `penumbra`: the executable that streams the hash (normally /proc/self/exe); `key`: the
  // Appendix A key of the stream (the same key gives the same stream, hence the same p-values).
  DieharderRun(std::string penumbra, std::string hash, std::vector<int> tests,
               std::uint32_t key = 0);
  ~DieharderRun();  // cancels and joins
  DieharderRun(const DieharderRun&) = delete;
  DieharderRun& operator=(const DieharderRun&) = delete;

  void start();
  void cancel();  // kills the running test's process group; the run ends as cancelled
  bool finished() const { return finished_; }
  bool cancelled() const { return cancel_; }
  int testsDone() const { return testsDone_; }
  int testsTotal() const { return int(tests_.size()); }
  const std::string& hash() const { return hash_; }
  std::vector<DieharderLine> lines() const;  // parsed so far
  std::string error() const;                 // "" unless a test could not be run

private:
  void work();
  std::string penumbra_, hash_;
  std::vector<int> tests_;
  std::uint32_t key_;
  std::thread thread_;
  std::atomic<bool> cancel_{false}, finished_{false};
  std::atomic<int> testsDone_{0}, childGroup_{0};
  mutable std::mutex mutex_;
  std::vector<DieharderLine> lines_;
  std::string error_;
};
