// Ctrl-C (SIGINT) and SIGTERM during a long command: the first asks the run to stop at its
// next check (core/run_control.h: between stages, frames, files, while ffmpeg runs), so the
// output's transaction is rolled back and nothing is left half-written (exit 1, "stopped");
// a second one ends the process at once (its temporary directory is removed by the next
// run of the same output, io/output_path.h). Installed while the object lives.
#pragma once

class InterruptCancels {
public:
  InterruptCancels();
  ~InterruptCancels();
  InterruptCancels(const InterruptCancels&) = delete;
  InterruptCancels& operator=(const InterruptCancels&) = delete;
};
