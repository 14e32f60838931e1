#include "window/views/ui_trace_source.h"
#include "monte_carlo/trace/trace_steps.h"
#include "shared_inputs/light/auto_params.h"

#include <cstdio>

#include "export/trace_json.h"
#include "window/ui_graph.h"
#include "window/ui_state.h"
#include "window/panels/ui_trace_panel.h"

namespace {

// 1. One gpu::TraceStep -> the panel's record (windows and points are GL texels already).
RayStepRecord convert(const gpu::TraceStep& step) {
  RayStepRecord record;
  record.level = step.header.y;
  record.windowLo = {step.window.x, step.window.y};
  record.windowHi = {step.window.z, step.window.w};
  record.zNearMin = step.depths.x;
  record.zFarMax = step.depths.y;
  record.rayDepthEnter = step.depths.z;
  record.rayDepthExit = step.depths.w;
  record.texelPoint = step.window.x >= 0 ? glm::vec2(step.stepping.z, step.stepping.w) : glm::vec2(-1);
  record.decision = stepDecisionName(step.header.z);
  record.stepping = step.stepping.y;
  // Linear search records each sample as a one-texel window without a level (search_linear.glsl).
  record.refinement = step.header.z == STEP_REFINE;
  record.point = step.header.y < 0 && step.window.x >= 0 &&
                 (step.header.z == STEP_SAMPLE || step.header.z == STEP_REFINE || step.header.z == STEP_HIT);
  return record;
}

// 1b. A point sample's band: the near and far layers at its texel (one read-back per layer
//     over the rectangle the samples cover, not one per sample).
void addLayerBands(const Frame& frame, std::vector<RayStepRecord>& steps) {
  const std::string nearKey = recordingInput(frame.pipeline, "near");
  const std::string farKey = recordingInput(frame.pipeline, "far");
  if (!frame.has(nearKey) || !frame.has(farKey)) return;
  glm::ivec2 lo{1 << 30}, hi{-1};
  for (const RayStepRecord& s : steps)
    if (s.point) {
      lo = glm::min(lo, s.windowLo);
      hi = glm::max(hi, s.windowLo);
    }
  if (hi.x < 0) return;
  const GlTexture& near = frame.texture(nearKey);
  const GlTexture& far = frame.texture(farKey);
  lo = glm::clamp(lo, glm::ivec2(0), glm::ivec2(near.width() - 1, near.height() - 1));
  hi = glm::clamp(hi, lo, glm::ivec2(near.width() - 1, near.height() - 1));
  const glm::ivec2 size = hi - lo + 1;
  const std::vector<float> nearValues = readRegion(near, lo.x, lo.y, size.x, size.y);
  const std::vector<float> farValues = readRegion(far, lo.x, lo.y, size.x, size.y);
  for (RayStepRecord& s : steps) {
    if (!s.point) continue;
    const glm::ivec2 at = glm::clamp(s.windowLo, lo, hi) - lo;
    const size_t index = size_t(at.y) * size_t(size.x) + size_t(at.x);
    if (index >= nearValues.size() || index >= farValues.size()) continue;
    s.zNearMin = nearValues[index];
    s.zFarMax = farValues[index];
  }
}

// 2. The steps of ray `ray` of the recorded pixel, if the recorded pixel is `pixel`.
RayTraceInfo stepsOfRay(const Frame& frame, glm::ivec2 pixel, int ray) {
  RayTraceInfo info;
  const Stage* recorder = recordingStage(frame.pipeline);
  if (!recorder) return info;
  const int n = effectiveRays(recorder->param(kRaysParam), lightAutoSettings(frame));
  info.raysPerPixel = n * n;
  const int recordX = recorder->param(kRecordXParam).asInt();
  const int recordY = recorder->param(kRecordYParam).asInt();
  if (recordX != pixel.x || recordY != frame.eyeHeight - 1 - pixel.y) {
    info.result = "recording this pixel on the next run";
    return info;
  }
  for (const gpu::TraceStep& step : recordedTraceSteps(frame))
    if (step.header.x == ray) info.steps.push_back(convert(step));
  addLayerBands(frame, info.steps);
  const std::string visibility = frame.pipeline.methodOutput(recorder->name());
  if (frame.has(visibility)) {
    char text[96];
    std::snprintf(text, sizeof text, "ray %d of %d; pixel visibility %.4g", ray, n * n,
                  double(readTexel(frame.texture(visibility), pixel.x, pixel.y)[0]));
    info.result = text;
  }
  return info;
}

}  // namespace

void installFrameTraceSource(ViewState& views) { views.traceSource = stepsOfRay; }

// 3. Eye-sized picks become the recorded pixel (image coordinates: row 0 at the top), and
//    the picked pixel of every stage that declares kCapabilityPicksEyePixel (raster4d's
//    mask, ssm's view of the light); the parameters' new revision re-runs the pipeline.
void recordPickedPixel(UiState& state) {
  if (!state.views.pick || !state.session.frame) return;
  // The eye of the coming run (UiState::keepPickInEye), so a resized eye runs once.
  const glm::ivec2 eye = state.fullEye != glm::ivec2(0) ? state.fullEye
                                                         : glm::ivec2(state.session.frame->eyeWidth, state.session.frame->eyeHeight);
  if (state.views.pickSpace != eye) return;
  const glm::ivec2 image{state.views.pick->x, state.views.pickSpace.y - 1 - state.views.pick->y};
  if (Stage* recorder = recordingStage(state.session.pipeline)) {
    recorder->param(kRecordXParam).value = image.x;
    recorder->param(kRecordYParam).value = image.y;
  }
  for (Stage* stage : stagesThatCan(state.session.pipeline, kCapabilityPicksEyePixel)) {
    stage->param(kPickXParam).value = image.x;
    stage->param(kPickYParam).value = image.y;
  }
}
