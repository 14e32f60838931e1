// Long runs announced and stoppable (README "Long runs"):
// - a stage whose cost grows with the scene (SSM's micro-patch quads, ...) estimates it from
//   the geometry before the expensive part and throws RunBudgetExceeded when it exceeds its
//   budget parameter: the CLI exits 2 naming the --set that runs it anyway; the window asks;
// - a run can be cancelled: requestRunCancel() from any thread (the CLI's --time-limit timer,
//   the window's Esc key or its Cancel button through the poll hook); the pipeline checks
//   between stages, SSM between batches of micro-patches, the reference between tiles. A cancelled run throws
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

// The shared shape of every stage's budget check: nothing when budgetMillions <= 0 (no limit)
// or estimateMillions <= budgetMillions; else throws RunBudgetExceeded with the message
// "<key>: this run would <what> (about E million), over <key>=B million. <fix>, or run it
// anyway with --set <key>=<1.25 E> (0: no limit)". Units are the key's own (its help says).
void checkRunBudget(const std::string& key, double estimateMillions, double budgetMillions,
                    const std::string& what, const std::string& fix);

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
// `where` is also kept as the run's progress (below).
void throwIfRunCancelled(const std::string& where);

// What a run is doing ("before stage ssm", "in reference, tile 40 of 192"), set by the checks
// above and by stages that report progress; for the window's "running" overlay. Any thread.
void setRunProgress(const std::string& where);
std::string runProgress();
// The window, before each run: starts the run's clock (and clears its progress).
void markRunStart();
double secondsSinceRunStart();
unsigned runSerial();  // counts markRunStart() calls: tells one run from the next

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
