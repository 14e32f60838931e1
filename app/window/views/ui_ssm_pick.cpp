#include "window/views/ui_ssm_pick.h"

#include "window/ui_state.h"

void pickSoftShadowMapTexels(UiState& state) {
  Pipeline& pipeline = state.session.pipeline;
  const auto& pick = state.views.pick;
  if (!pick || !state.session.frame || !pipeline.hasStage("ssm")) return;
  Stage& ssm = pipeline.stage("ssm");
  const glm::ivec2 eye(state.session.frame->eyeWidth, state.session.frame->eyeHeight);
  int maps = ssm.param("resolution").asInt();
  if (ssm.param("resolution").automatic) {  // the size auto chose in the last run (auto_ssm.h)
    const auto chosen = state.session.frame->counters.find("auto.ssm_resolution");
    if (chosen != state.session.frame->counters.end()) maps = int(chosen->second);
  }
  if (state.views.pickSpace == eye) {  // image coordinates: row 0 at the top
    ssm.param("pick_x").value = pick->x;
    ssm.param("pick_y").value = eye.y - 1 - pick->y;
  } else if (state.views.pickSpace == glm::ivec2(maps)) {  // GL texel of the light-space maps
    ssm.param("patch_x").value = pick->x;
    ssm.param("patch_y").value = pick->y;
  }
}
