// A time limit for unattended runs (--screenshot, --script): if the run has not finished
// after `seconds`, it prints what it was doing and exits with status 3, so a test or a
// report job fails with a message instead of hanging. $PENUMBRA_WATCHDOG_SECONDS overrides
// the limit (0 disables it).
#pragma once
#include <atomic>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

class Watchdog {
public:
  Watchdog(const std::string& what, int seconds);
  ~Watchdog();  // disarms
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;

private:
  std::mutex mutex_;
  std::condition_variable finished_;
  bool done_ = false;
  std::thread thread_;
};
