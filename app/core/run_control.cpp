#include "core/run_control.h"

#include <atomic>
#include <chrono>
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

}  // namespace

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

void throwIfRunCancelled(const std::string& where) {
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
