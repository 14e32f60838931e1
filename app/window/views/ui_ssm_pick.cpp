#include "window/views/ui_ssm_pick.h"

#include "window/ui_graph.h"
#include "window/ui_state.h"

void pickStageMapTexels(UiState& state) {
  const auto& pick = state.views.pick;
  if (!pick || !state.session.frame) return;
  const glm::ivec2 eye(state.session.frame->eyeWidth, state.session.frame->eyeHeight);
  if (state.views.pickSpace == eye) return;  // an eye pick: the stages' picked pixel
  for (Stage* stage : stagesThatCan(state.session.pipeline, kCapabilityPicksMapTexel)) {
    int maps = stage->param(kMapResolutionParam).asInt();
    if (stage->param(kMapResolutionParam).automatic) {  // the size auto chose in the last run (auto_ssm.h)
      const auto& counters = state.session.frame->counters;
      const auto chosen = counters.find("auto." + stage->name() + "_resolution");
      if (chosen != counters.end()) maps = int(chosen->second);
    }
    if (state.views.pickSpace != glm::ivec2(maps)) continue;
    stage->param(kPatchXParam).value = pick->x;  // GL texel of the light-space maps
    stage->param(kPatchYParam).value = pick->y;
  }
}
