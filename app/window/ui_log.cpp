#include "window/ui_log.h"

#include <cstdio>
#include <ctime>

namespace {

constexpr std::size_t kRepeatWindow = 8;  // a repeat of one of the last 8 entries is counted

std::string clockNow() {
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char text[16];
  std::strftime(text, sizeof text, "%H:%M:%S", &local);
  return text;
}

}  // namespace

UiLog::UiLog() : start_(std::chrono::steady_clock::now()) {}

void UiLog::add(LogLevel level, const std::string& source, const std::string& message) {
  if (message.empty()) return;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const std::size_t first = entries_.size() > kRepeatWindow ? entries_.size() - kRepeatWindow : 0;
  for (std::size_t i = entries_.size(); i-- > first;) {
    LogEntry& entry = entries_[i];
    if (entry.level == level && entry.source == source && entry.message == message) {
      ++entry.repeats;
      entry.seconds = seconds;
      entry.clock = clockNow();
      return;
    }
  }
  entries_.push_back({seconds, clockNow(), level, source, message, 1});
  (level == LogLevel::Warning ? warnings_ : errors_) += 1;
  ++added_;
  if (entries_.size() > kLimit) {
    entries_.pop_front();
    ++dropped_;
  }
  if (echo) {
    std::fprintf(stderr, "penumbra: %s %s: %s\n", level == LogLevel::Warning ? "warning" : "error",
                 source.c_str(), message.c_str());
    std::fflush(stderr);
  }
}

void UiLog::clear() {
  entries_.clear();
  read_ = added_;
}

std::string UiLog::line(const LogEntry& entry) {
  std::string text = entry.clock + "  " + (entry.level == LogLevel::Warning ? "warning" : "error  ") + "  " +
                     entry.source + ": " + entry.message;
  if (entry.repeats > 1) text += " (x" + std::to_string(entry.repeats) + ")";
  return text;
}

std::string UiLog::text() const {
  std::string all;
  for (const LogEntry& entry : entries_) all += line(entry) + "\n";
  return all;
}
