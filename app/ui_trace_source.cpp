#include "ui_trace_source.h"

#include <cstdio>

#include "trace_command.h"
#include "ui_state.h"
#include "ui_trace_panel.h"

namespace {

bool hasParameter(const Pipeline& pipeline, const std::string& key) {
  for (const std::string& each : pipeline.paramKeys())
    if (each == key) return true;
  return false;
}

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
  return record;
}

// 2. The steps of ray `ray` of the recorded pixel, if the recorded pixel is `pixel`.
RayTraceInfo stepsOfRay(const Frame& frame, glm::ivec2 pixel, int ray) {
  RayTraceInfo info;
  if (!hasParameter(frame.pipeline, "trace.record_x")) return info;
  const int n = frame.pipeline.param("trace.rays").asInt();
  info.raysPerPixel = n * n;
  const int recordX = frame.pipeline.param("trace.record_x").asInt();
  const int recordY = frame.pipeline.param("trace.record_y").asInt();
  if (recordX != pixel.x || recordY != frame.eyeHeight - 1 - pixel.y) {
    info.result = "recording this pixel on the next run";
    return info;
  }
  for (const gpu::TraceStep& step : frame.traceSteps)
    if (step.header.x == ray) info.steps.push_back(convert(step));
  if (frame.has("trace.visibility")) {
    char text[96];
    std::snprintf(text, sizeof text, "ray %d of %d; pixel visibility %.4g", ray, n * n,
                  double(readTexel(frame.input("trace.visibility"), pixel.x, pixel.y)[0]));
    info.result = text;
  }
  return info;
}

}  // namespace

void installFrameTraceSource() { rayTraceSource() = stepsOfRay; }

// 3. Eye-sized picks become the recorded pixel (image coordinates: row 0 at the top).
void recordPickedPixel(UiState& state) {
  if (!state.pick || !state.frame || !hasParameter(state.pipeline, "trace.record_x")) return;
  if (state.pickSpace != glm::ivec2(state.frame->eyeWidth, state.frame->eyeHeight)) return;
  const glm::ivec2 image{state.pick->x, state.pickSpace.y - 1 - state.pick->y};
  Param& x = state.pipeline.param("trace.record_x");
  Param& y = state.pipeline.param("trace.record_y");
  if (x.asInt() == image.x && y.asInt() == image.y) return;
  x.value = image.x;
  y.value = image.y;
  state.dirty = true;
}
