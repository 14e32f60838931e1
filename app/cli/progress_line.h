// The command line's progress bar (core/progress.h) on stderr, for tasks that run past a
// second: on a terminal one line redrawn in place ("\r", at most 10 times a second); into
// a file or pipe (logs, CI) a plain line at every further 10 %, so a log stays short and
// readable. Installed while the object lives.
#pragma once
#include <string>

class CliProgress {
public:
  explicit CliProgress(std::string command);
  ~CliProgress();
  CliProgress(const CliProgress&) = delete;
  CliProgress& operator=(const CliProgress&) = delete;
};
