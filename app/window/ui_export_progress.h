// Progress of the window's long exports (core/progress.h, decision 130):
// - "Export all" (the button, Ctrl+E) runs between two UI frames, not inside one, so the
//   run overlay (panels/ui_run_budget.h) can show its bar and Cancel while it writes;
// - a lesson or script played through unattended (`penumbra lesson --export`) is one task,
//   a step per action: the command line's bar on stderr (app/cli/progress_line.h).
#pragma once
#include <cstddef>
#include <string>

class UiState;
class ScriptRunner;

// The button and the shortcut: exported before the next UI frame ("" -> the default folder).
void requestExportAll(const std::string& directory);
// The frame loop, outside the UI frame: a requested "Export all", and the script's progress
// (`runner` may be null; only unattended runs are counted).
void exportsBetweenFrames(UiState& state, const ScriptRunner* runner, bool unattended);
