#include "cli/interrupt.h"

#include <signal.h>

#include <csignal>

#include "core/run_control.h"

namespace {

volatile std::sig_atomic_t interrupts = 0;
volatile std::sig_atomic_t lastSignal = 0;
struct sigaction previousInt {}, previousTerm {};

// Async-signal-safe: counts, and on the second signal restores the default and re-raises.
void onSignal(int signal) {
  lastSignal = signal;
  if (++interrupts >= 2) {
    ::signal(signal, SIG_DFL);
    ::raise(signal);
  }
}

}  // namespace

InterruptCancels::InterruptCancels() {
  interrupts = 0;
  struct sigaction action {};
  action.sa_handler = onSignal;
  sigemptyset(&action.sa_mask);
  // A signal the parent set to be ignored stays ignored (a shell does so for SIGINT of a
  // command started with `&`: Ctrl-C at the terminal is not meant for it).
  ::sigaction(SIGINT, nullptr, &previousInt);
  ::sigaction(SIGTERM, nullptr, &previousTerm);
  if (previousInt.sa_handler != SIG_IGN) ::sigaction(SIGINT, &action, nullptr);
  if (previousTerm.sa_handler != SIG_IGN) ::sigaction(SIGTERM, &action, nullptr);
  // Turned into a cancel request outside the handler, at the run's next check.
  setRunCancelPoll([] {
    if (interrupts > 0) requestRunCancel(lastSignal == SIGTERM ? "SIGTERM" : "Ctrl-C");
  });
}

InterruptCancels::~InterruptCancels() {
  setRunCancelPoll(nullptr);
  ::sigaction(SIGINT, &previousInt, nullptr);
  ::sigaction(SIGTERM, &previousTerm, nullptr);
}
