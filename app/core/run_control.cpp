#include "core/run_control.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <thread>

namespace {

std::atomic<bool> cancelled{false};
bool stickyCancel = false;
std::mutex reasonMutex;
std::string reason;
std::function<void()> pollHook;
std::chrono::steady_clock::time_point lastPoll;
std::string progress;  // under reasonMutex
std::chrono::steady_clock::time_point runStart = std::chrono::steady_clock::now();
std::atomic<unsigned> serial{0};

}  // namespace

void checkRunBudget(const std::string& key, double estimateMillions, double budgetMillions,
                    const std::string& what, const std::string& fix) {
  if (budgetMillions <= 0 || !(estimateMillions > budgetMillions)) return;
  char numbers[160];
  std::snprintf(numbers, sizeof numbers, " (about %.4g million), over %s=%g million. ",
                estimateMillions, key.c_str(), budgetMillions);
  char override[96];
  std::snprintf(override, sizeof override, ", or run it anyway with --set %s=%.0f (0: no limit)",
                key.c_str(), std::ceil(estimateMillions * 1.25));
  throw RunBudgetExceeded(key + ": this run would " + what + numbers + fix + override, key,
                          estimateMillions, budgetMillions);
}

void requestRunCancel(const std::string& why, bool sticky) {
  {
    std::lock_guard<std::mutex> lock(reasonMutex);
    if (!cancelled) reason = why;
    stickyCancel = stickyCancel || sticky;
  }
  cancelled = true;
}

bool runCancelRequested() { return cancelled; }

std::string runCancelReason() {
  std::lock_guard<std::mutex> lock(reasonMutex);
  return reason;
}

void clearRunCancel() {
  std::lock_guard<std::mutex> lock(reasonMutex);
  if (stickyCancel) return;
  cancelled = false;
  reason.clear();
}

void setRunCancelPoll(std::function<void()> poll) { pollHook = std::move(poll); }

void pollRunCancel() {
  if (!pollHook) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - lastPoll < std::chrono::milliseconds(50)) return;
  lastPoll = now;
  pollHook();
}

void setRunProgress(const std::string& where) {
  std::lock_guard<std::mutex> lock(reasonMutex);
  progress = where;
}

std::string runProgress() {
  std::lock_guard<std::mutex> lock(reasonMutex);
  return progress;
}

void markRunStart() {
  {
    std::lock_guard<std::mutex> lock(reasonMutex);
    progress.clear();
    runStart = std::chrono::steady_clock::now();
  }
  ++serial;
}

double secondsSinceRunStart() {
  std::lock_guard<std::mutex> lock(reasonMutex);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - runStart).count();
}

unsigned runSerial() { return serial; }

void throwIfRunCancelled(const std::string& where) {
  setRunProgress(where);
  pollRunCancel();
  if (cancelled) throw RunCancelled("cancelled " + where + " (" + runCancelReason() + ")");
}

struct RunTimeLimit::State {
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  std::thread thread;
};

RunTimeLimit::RunTimeLimit(double seconds, double grace) {
  if (!(seconds > 0)) return;
  state_ = new State;
  State* state = state_;
  state->thread = std::thread([state, seconds, grace] {
    std::unique_lock<std::mutex> lock(state->mutex);
    const auto limit = std::chrono::duration<double>(seconds);
    if (state->finished.wait_for(lock, limit, [state] { return state->done; })) return;
    char text[80];
    std::snprintf(text, sizeof text, "time limit of %g s reached", seconds);
    requestRunCancel(text, /*sticky=*/true);
    if (state->finished.wait_for(lock, std::chrono::duration<double>(grace),
                                 [state] { return state->done; }))
      return;
    std::fprintf(stderr, "penumbra: %s and the run did not stop within %g s more; exiting\n",
                 text, grace);
    std::fflush(stderr);
    std::_Exit(3);
  });
}

RunTimeLimit::~RunTimeLimit() {
  if (!state_) return;
  {
    std::lock_guard<std::mutex> lock(state_->mutex);
    state_->done = true;
  }
  state_->finished.notify_all();
  state_->thread.join();
  delete state_;
}
