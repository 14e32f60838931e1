// Progress of a long export (README "Video export"; docs/decisions/130-video-export.md):
// one task at a time per process, counted in steps (frames, files, encodes). A task shows
// itself only after it has run for a second (shorter ones stay silent), through the
// reporter the program installed: the command line's bar on stderr (app/cli/
// progress_line.h), the window's progress bar. A task inside another (the files of one
// frame inside a video's frames) only checks for a cancel: the outer one is what is shown.
#pragma once
#include <functional>
#include <string>

struct ProgressState {
  bool active = false;
  std::string task;    // "export video", "export"
  std::string detail;  // what the last step was: "frame 12 of 96 (t = 0.5 s)"
  int done = 0, total = 0;
  double seconds = 0;  // since the task began
  double fraction() const { return total > 0 ? double(done) / double(total) : 0.0; }
};

// Seconds a task runs before it is reported (PENUMBRA_PROGRESS_AFTER overrides, for tests).
double progressDelaySeconds();

class ProgressTask {
public:
  ProgressTask(const std::string& task, int total);
  ~ProgressTask();  // the task ends (a finished bar ends its line)
  ProgressTask(const ProgressTask&) = delete;
  ProgressTask& operator=(const ProgressTask&) = delete;
  // One more step done (or `steps`); then throwIfRunCancelled(detail) (core/run_control.h):
  // a long export stops at its next step when Ctrl-C, Esc or Cancel asked.
  void advance(const std::string& detail, int steps = 1);
  // The detail of work under way inside a step (an encode), without counting a step.
  void describe(const std::string& detail);
  bool outermost() const { return outermost_; }

private:
  bool outermost_ = false;
};

// The outermost task now (active false when none).
ProgressState currentProgress();
// Called after each step of an outermost task that has run past progressDelaySeconds(),
// and once with `finished` when such a task ends. One reporter per process; null: none.
using ProgressReporter = std::function<void(const ProgressState&, bool finished)>;
void setProgressReporter(ProgressReporter reporter);
