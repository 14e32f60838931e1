// Long runs announced and stoppable (README "Long runs"):
// - a stage whose cost grows with the scene (SSM's micro-patch quads, ...) estimates it from
//   the geometry before the expensive part and throws RunBudgetExceeded when it exceeds its
//   budget parameter: the CLI exits 2 naming the --set that runs it anyway; the window asks;
// - a run can be cancelled: requestRunCancel() from any thread (the CLI's --time-limit timer,
//   the window's Esc key through the poll hook); the pipeline checks between stages, SSM
//   between batches of micro-patches, the reference between rows. A cancelled run throws
//   RunCancelled, so nothing downstream runs on partial data and no export is written.
#pragma once
#include <functional>
#include <stdexcept>
#include <string>

#include "base/input_error.h"

// Over budget: bad input in the sense of main() (exit 2), with what it would cost.
struct RunBudgetExceeded : InputError {
  RunBudgetExceeded(const std::string& message, std::string budgetKey, double estimate,
                    double budget)
      : InputError(message), budgetKey(std::move(budgetKey)), estimate(estimate), budget(budget) {}
  std::string budgetKey;  // "ssm.budget": the parameter that lets it run
  double estimate, budget;  // in that parameter's unit
};

// Stopped on request: an internal failure in the sense of main() (exit 1), not bad input.
struct RunCancelled : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Any thread. The reason is kept for the message ("time limit of 5 s reached", "Esc").
// A sticky request (the time limit) stays until the process ends; clearRunCancel() (the
// window, before each run) clears only the others.
void requestRunCancel(const std::string& reason, bool sticky = false);
bool runCancelRequested();
std::string runCancelReason();
void clearRunCancel();

// The thread that runs the pipeline: a hook that may call requestRunCancel() (the window
// polls its events and the Esc key there). pollRunCancel() calls it at most every 50 ms.
void setRunCancelPoll(std::function<void()> poll);
void pollRunCancel();
// pollRunCancel(), then throws RunCancelled naming `where` if a cancel was requested.
void throwIfRunCancelled(const std::string& where);

// A limit on a whole command: after `seconds`, requests a cancel (the run stops at the next
// check and the command exits 1 with nothing half-written); if it has still not returned
// `grace` seconds later, prints so and exits with status 3 (a GL call that never returns).
// 0 or less: no limit. Disarmed when destroyed.
class RunTimeLimit {
public:
  explicit RunTimeLimit(double seconds, double grace = 30);
  ~RunTimeLimit();
  RunTimeLimit(const RunTimeLimit&) = delete;
  RunTimeLimit& operator=(const RunTimeLimit&) = delete;

private:
  struct State;
  State* state_ = nullptr;
};
