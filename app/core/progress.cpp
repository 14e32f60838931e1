#include "core/progress.h"

#include <chrono>
#include <cstdlib>
#include <mutex>

#include "core/run_control.h"

namespace {

std::mutex mutex;
ProgressState state;  // under mutex
int depth = 0;
bool reported = false;  // the current task was shown at least once
std::chrono::steady_clock::time_point started;
ProgressReporter reporter;

double elapsed() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

// Outside the lock: the reporter may take long (a terminal) or draw (the window).
void report(bool finished) {
  ProgressState copy;
  ProgressReporter call;
  {
    std::lock_guard<std::mutex> lock(mutex);
    state.seconds = elapsed();
    if (!reporter || (!reported && state.seconds < progressDelaySeconds())) return;
    if (finished && !reported) return;
    reported = true;
    copy = state;
    call = reporter;
  }
  call(copy, finished);
}

}  // namespace

double progressDelaySeconds() {
  static const double delay = [] {
    const char* text = std::getenv("PENUMBRA_PROGRESS_AFTER");
    if (!text || !*text) return 1.0;
    char* end = nullptr;
    const double value = std::strtod(text, &end);
    return (*end || !(value >= 0) || value > 1e6) ? 1.0 : value;
  }();
  return delay;
}

ProgressTask::ProgressTask(const std::string& task, int total) {
  std::lock_guard<std::mutex> lock(mutex);
  outermost_ = depth++ == 0;
  if (!outermost_) return;
  state = ProgressState{true, task, "", 0, total, 0};
  reported = false;
  started = std::chrono::steady_clock::now();
}

ProgressTask::~ProgressTask() {
  if (outermost_) report(true);
  std::lock_guard<std::mutex> lock(mutex);
  --depth;
  if (outermost_) state = ProgressState{};
}

void ProgressTask::advance(const std::string& detail, int steps) {
  if (outermost_) {
    {
      std::lock_guard<std::mutex> lock(mutex);
      state.done += steps;
      state.detail = detail;
    }
    report(false);
  }
  throwIfRunCancelled(detail);
}

void ProgressTask::describe(const std::string& detail) {
  if (!outermost_) return;
  {
    std::lock_guard<std::mutex> lock(mutex);
    state.detail = detail;
  }
  report(false);
}

ProgressState currentProgress() {
  std::lock_guard<std::mutex> lock(mutex);
  ProgressState copy = state;
  if (copy.active) copy.seconds = elapsed();
  return copy;
}

void setProgressReporter(ProgressReporter next) {
  std::lock_guard<std::mutex> lock(mutex);
  reporter = std::move(next);
}
