// The session's log (one part of UiState, app/window/ui_state.h): every warning and error the
// window met, whole, with the time and where it came from: scene warnings (scene_checks.h and
// the loaders), failed runs, failed actions (exports, settings, selections), shader compile
// errors, script errors and exceptions caught by the frame loop. The status line shows the
// count and the last one; the log panel shows them all; in window mode each new line is also
// written to stderr, so a terminal shows what the window showed. No ImGui here: scripts and
// tests read the log as they read the rest of the state ("print_log", UiLog::text).
#pragma once
#include <chrono>
#include <cstddef>
#include <deque>
#include <string>

enum class LogLevel { Warning, Error };

struct LogEntry {
  double seconds = 0;       // since the log was made (the window opened)
  std::string clock;        // local time, "HH:MM:SS"
  LogLevel level = LogLevel::Error;
  std::string source;       // "scene", "pipeline", "shaders", "export", "settings", "script", ...
  std::string message;      // whole: never cut
  int repeats = 1;          // the same source and message again, soon after (counted, not repeated)
};

class UiLog {
public:
  UiLog();
  // Adds an entry, or counts a repeat of one of the last few (a slider dragged through the
  // same failure). A new entry goes to stderr when echo is on.
  void add(LogLevel level, const std::string& source, const std::string& message);
  void warning(const std::string& source, const std::string& message) { add(LogLevel::Warning, source, message); }
  void error(const std::string& source, const std::string& message) { add(LogLevel::Error, source, message); }

  const std::deque<LogEntry>& entries() const { return entries_; }
  int warnings() const { return warnings_; }  // entries ever added, repeats counted once
  int errors() const { return errors_; }
  int unread() const { return int(added_ - read_); }  // added since the panel was last shown
  void markRead() { read_ = added_; }
  std::size_t dropped() const { return dropped_; }  // oldest entries let go past kLimit
  void clear();

  // "12:03:04  warning  scene: the light sits inside ... (x3)"
  static std::string line(const LogEntry& entry);
  std::string text() const;  // every line, oldest first, one per line

  bool echo = false;  // also write new entries to stderr (window mode)
  static constexpr std::size_t kLimit = 2000;

private:
  std::chrono::steady_clock::time_point start_;
  std::deque<LogEntry> entries_;
  int warnings_ = 0, errors_ = 0;
  std::size_t added_ = 0, read_ = 0, dropped_ = 0;
};
