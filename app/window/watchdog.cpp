#include "window/watchdog.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>

Watchdog::Watchdog(const std::string& what, int seconds) {
  if (const char* override = std::getenv("PENUMBRA_WATCHDOG_SECONDS")) seconds = std::atoi(override);
  if (seconds <= 0) return;
  thread_ = std::thread([this, what, seconds] {
    std::unique_lock<std::mutex> lock(mutex_);
    if (finished_.wait_for(lock, std::chrono::seconds(seconds), [this] { return done_; })) return;
    std::fprintf(stderr, "penumbra: %s did not finish within %d s; stopping (watchdog)\n",
                 what.c_str(), seconds);
    std::fflush(stderr);
    std::_Exit(3);
  });
}

Watchdog::~Watchdog() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    done_ = true;
  }
  finished_.notify_all();
  if (thread_.joinable()) thread_.join();
}
