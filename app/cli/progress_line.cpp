#include "cli/progress_line.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "core/progress.h"

CliProgress::CliProgress(std::string command) {
  const bool terminal = ::isatty(STDERR_FILENO) == 1;
  struct Shown {
    int decile = -1;
    double drawn = -1;
    bool open = false;  // a terminal line without its newline yet
  };
  auto shown = std::make_shared<Shown>();
  setProgressReporter([command, terminal, shown](const ProgressState& state, bool finished) {
    const int percent = int(std::floor(100 * state.fraction()));
    if (terminal) {
      if (!finished && shown->drawn >= 0 && state.seconds - shown->drawn < 0.1) return;
      shown->drawn = state.seconds;
      constexpr int kWidth = 30;
      const int filled = int(std::lround(kWidth * state.fraction()));
      std::string bar(size_t(filled), '#');
      bar.append(size_t(kWidth - filled), '-');
      std::fprintf(stderr, "\rpenumbra %s: [%s] %3d%% %s  %.1f s\x1b[K", command.c_str(), bar.c_str(),
                   percent, state.detail.c_str(), state.seconds);
      shown->open = true;
      if (finished) {
        std::fputs(state.done < state.total ? "  (stopped)\n" : "\n", stderr);
        shown->open = false;
      }
      std::fflush(stderr);
      return;
    }
    const int decile = percent / 10;
    if (finished) {
      std::fprintf(stderr, "penumbra %s: %s %d of %d steps (%d%%) in %.1f s\n", command.c_str(),
                   state.done < state.total ? "stopped after" : "done:", state.done, state.total,
                   percent, state.seconds);
      return;
    }
    if (decile <= shown->decile) return;
    shown->decile = decile;
    std::fprintf(stderr, "penumbra %s: %3d%% %s, %.1f s\n", command.c_str(), percent,
                 state.detail.c_str(), state.seconds);
  });
}

CliProgress::~CliProgress() { setProgressReporter(nullptr); }
