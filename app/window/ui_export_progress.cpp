#include "window/ui_export_progress.h"

#include <memory>
#include <optional>

#include "core/progress.h"
#include "core/run_control.h"
#include "window/panels/ui_export.h"
#include "window/script/ui_script.h"
#include "window/ui_state.h"

void requestExportAll(UiState& state, const std::string& directory) {
  state.panelMemory.exportProgress.pendingExportAll = directory;
}

void exportsBetweenFrames(UiState& state, const ScriptRunner* runner, bool unattended) {
  ExportProgressState& progress = state.panelMemory.exportProgress;
  std::optional<std::string>& pendingExportAll = progress.pendingExportAll;
  std::unique_ptr<ProgressTask>& scriptTask = progress.scriptTask;
  size_t& scriptStepsCounted = progress.scriptStepsCounted;
  if (pendingExportAll) {
    const std::string directory = *pendingExportAll;
    pendingExportAll.reset();
    clearRunCancel();  // Esc and Cancel stop this export, not an earlier run
    markRunStart();    // the overlay's clock: shown once the export has taken a second
    state.reportExport(exportAllStages(state, directory));
  }
  if (!runner || !unattended) {
    scriptTask.reset();
    return;
  }
  if (!scriptTask && runner->done() < runner->total()) {
    scriptTask = std::make_unique<ProgressTask>("script", int(runner->total()));
    scriptStepsCounted = 0;
  }
  if (!scriptTask) return;
  if (runner->done() > scriptStepsCounted) {
    const int steps = int(runner->done() - scriptStepsCounted);
    scriptStepsCounted = runner->done();
    scriptTask->advance("action " + std::to_string(scriptStepsCounted) + " of " +
                            std::to_string(runner->total()), steps);
  }
  if (scriptStepsCounted >= runner->total()) scriptTask.reset();
}
