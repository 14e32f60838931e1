// Another program run as a child (ffmpeg for the video export, decision 130): started
// from an argument vector (no shell, so no quoting of paths), stdin and stdout on
// /dev/null, its stderr captured (the last 16 KiB) for the message when it fails.
// Cancellable: while it runs, the run-cancel flag is polled every 50 ms (core/
// run_control.h: Ctrl-C, Esc, the window's Cancel); a cancel ends the child (SIGTERM, then
// SIGKILL after 2 s), waits for it and throws RunCancelled.
#pragma once
#include <string>
#include <vector>

// The absolute path of `name` on $PATH (executable regular file), or "".
std::string findExecutable(const std::string& name);

struct ChildResult {
  int exitStatus = -1;  // the exit status, or 128 + signal when a signal ended it
  std::string errorOutput;  // stderr (its tail)
};

// Runs argv[0] (a path, or a name looked up on $PATH) with `argv`. Throws std::runtime_error
// when it cannot start, RunCancelled when cancelled.
ChildResult runChild(const std::vector<std::string>& argv);
