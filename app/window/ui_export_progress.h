// Progress of the window's long exports (core/progress.h, decision 130):
// - "Export all" (the button, Ctrl+E) runs between two UI frames, not inside one, so the
//   run overlay (panels/ui_run_budget.h) can show its bar and Cancel while it writes;
// - a lesson or script played through unattended (`penumbra lesson --export`) is one task,
//   a step per action: the command line's bar on stderr (app/cli/progress_line.h).
#pragma once
#include <cstddef>
#include <memory>
#include <optional>
#include <string>

#include "core/progress.h"

class UiState;
class ScriptRunner;

// What the frame loop keeps between frames (UiState::panelMemory.exportProgress); destroyed
// with the UiState, before the process's own statics (core/progress.cpp) go.
struct ExportProgressState {
  std::optional<std::string> pendingExportAll;  // "Export all" asked for, not yet done
  std::unique_ptr<ProgressTask> scriptTask;     // the unattended script's task, a step per action
  size_t scriptStepsCounted = 0;
};

// The button and the shortcut: exported before the next UI frame ("" -> the default folder).
void requestExportAll(UiState& state, const std::string& directory);
// The frame loop, outside the UI frame: a requested "Export all", and the script's progress
// (`runner` may be null; only unattended runs are counted).
void exportsBetweenFrames(UiState& state, const ScriptRunner* runner, bool unattended);
