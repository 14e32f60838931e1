#include "window/views/ui_ssm_pick.h"

#include "window/ui_state.h"

namespace {


// Sets stage.key_x / key_y to `texel`; true when they changed.
bool setPair(Pipeline& pipeline, const std::string& x, const std::string& y, glm::ivec2 texel) {
  Param& px = pipeline.param(x);
  Param& py = pipeline.param(y);
  if (px.asInt() == texel.x && py.asInt() == texel.y) return false;
  px.value = texel.x;
  py.value = texel.y;
  return true;
}

}  // namespace

void pickSoftShadowMapTexels(UiState& state) {
  if (!state.pick || !state.frame || !state.pipeline.hasStage("ssm")) return;
  const glm::ivec2 eye(state.frame->eyeWidth, state.frame->eyeHeight);
  const int maps = state.pipeline.param("ssm.resolution").asInt();
  if (state.pickSpace == eye) {  // image coordinates: row 0 at the top
    const glm::ivec2 image{state.pick->x, eye.y - 1 - state.pick->y};
    state.dirty |= setPair(state.pipeline, "ssm.pick_x", "ssm.pick_y", image);
  } else if (state.pickSpace == glm::ivec2(maps)) {  // GL texel of the light-space maps
    state.dirty |= setPair(state.pipeline, "ssm.patch_x", "ssm.patch_y", *state.pick);
  }
}
