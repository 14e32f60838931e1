#include "window/ui_widgets.h"
#include "window/panels/ui_trace_panel.h"

#include <imgui.h>

#include <algorithm>

#include "export/trace_json.h"
#include "window/ui_state.h"

// Level colours: a small categorical ramp, repeating past 8 levels.
unsigned levelColor(int level) {
  static const ImU32 colors[8] = {IM_COL32(250, 220, 90, 255),  IM_COL32(90, 210, 220, 255),
                                  IM_COL32(60, 200, 90, 255),   IM_COL32(240, 150, 60, 255),
                                  IM_COL32(160, 90, 220, 255),  IM_COL32(220, 60, 60, 255),
                                  IM_COL32(40, 110, 230, 255),  IM_COL32(200, 200, 200, 255)};
  return level < 0 ? IM_COL32(235, 235, 235, 255) : colors[level % 8];  // -1: linear samples
}

unsigned pointColor(const RayStepRecord& step) {
  if (step.decision == "hit") return IM_COL32(255, 70, 60, 255);
  return step.refinement ? IM_COL32(255, 160, 40, 255) : IM_COL32(240, 240, 240, 255);
}

// The path from the light to the receiver: windows (hierarchical) or dots (linear), and the
// projected ray through the step ends, in stepping order (refinements lie between samples).
std::vector<ViewOverlayShape> traceOverlay(const RayTraceInfo& trace, glm::ivec2 lightMapSize) {
  std::vector<ViewOverlayShape> overlay;
  std::vector<std::pair<float, glm::vec2>> path;
  for (size_t i = 0; i < trace.steps.size(); ++i) {
    const RayStepRecord& s = trace.steps[i];
    if (s.point && s.texelPoint.x >= 0)
      overlay.push_back({lightMapSize, s.texelPoint, s.texelPoint, pointColor(s), false,
                         s.refinement ? 2.5f : 3.5f});
    else if (s.windowLo.x >= 0)
      overlay.push_back({lightMapSize, glm::vec2(s.windowLo), glm::vec2(s.windowHi + 1),
                         levelColor(s.level), false});
    if (s.texelPoint.x >= 0) path.push_back({s.stepping >= 0 ? s.stepping : float(i), s.texelPoint});
  }
  std::stable_sort(path.begin(), path.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<ViewOverlayShape> shapes;  // the path first: windows and dots draw over it
  for (size_t i = 1; i < path.size(); ++i)
    shapes.push_back({lightMapSize, path[i - 1].second, path[i].second, 0xffffffffu, true});
  shapes.insert(shapes.end(), overlay.begin(), overlay.end());
  return shapes;
}

namespace {

bool hasPoints(const std::vector<RayStepRecord>& steps) {
  for (const RayStepRecord& s : steps)
    if (s.point) return true;
  return false;
}

// 1a. Point samples (linear search): x = stepping, the ray's depth as a line through the
//     samples, each sample's [near, far] as a bar (coloured like level 0) and the sample as a
//     dot. A dot inside its bar is inside the solid the two layers bound: a hit (§3.3).
void drawPointPlot(const std::vector<RayStepRecord>& steps) {
  const ImVec2 size{ImGui::GetContentRegionAvail().x, uiPixels(140)};
  const ImVec2 at = ImGui::GetCursorScreenPos();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(at, {at.x + size.x, at.y + size.y}, IM_COL32(20, 20, 24, 255));
  std::vector<const RayStepRecord*> points;
  float low = 1, high = 0, sLow = 1, sHigh = 0;
  for (const RayStepRecord& s : steps) {
    if (!s.point || s.stepping < 0) continue;
    points.push_back(&s);
    low = std::min(low, s.rayDepthExit);
    high = std::max(high, s.rayDepthExit);
    if (s.zNearMin <= s.zFarMax) {
      low = std::min(low, s.zNearMin);
      high = std::max(high, s.zFarMax);
    }
    sLow = std::min(sLow, s.stepping);
    sHigh = std::max(sHigh, s.stepping);
  }
  if (high <= low) high = low + 1;
  if (sHigh <= sLow) sHigh = sLow + 1;
  const auto x = [&](float s) { return at.x + 6 + (s - sLow) / (sHigh - sLow) * (size.x - 12); };
  const auto y = [&](float depth) { return at.y + 4 + (depth - low) / (high - low) * (size.y - 8); };
  std::stable_sort(points.begin(), points.end(),
                   [](const RayStepRecord* a, const RayStepRecord* b) { return a->stepping < b->stepping; });
  for (const RayStepRecord* s : points)
    if (s->zNearMin <= s->zFarMax)
      draw->AddRectFilled({x(s->stepping) - 1.5f, y(s->zNearMin)}, {x(s->stepping) + 1.5f, y(s->zFarMax) + 1},
                          (levelColor(0) & 0x00ffffff) | 0xa0000000);
  for (size_t i = 1; i < points.size(); ++i)
    draw->AddLine({x(points[i - 1]->stepping), y(points[i - 1]->rayDepthExit)},
                  {x(points[i]->stepping), y(points[i]->rayDepthExit)}, IM_COL32(150, 150, 150, 255), 1);
  for (const RayStepRecord* s : points)
    draw->AddCircleFilled({x(s->stepping), y(s->rayDepthExit)}, s->refinement ? 2.5f : 3.0f, pointColor(*s));
  ImGui::Dummy(size);
  ImGui::PushTextWrapPos(0);
  ImGui::TextDisabled("x: stepping (light -> receiver); y: light depth (down: farther). "
                      "Dots: samples (white), refinements (orange), hit (red); "
                      "yellow bars: the layers' near..far at each sample.");
  ImGui::PopTextWrapPos();
}

// 1b. The plot: x = step, y = light depth (0 at the top: nearer the light). Each step draws
//    its neighbourhood's [zNearMin, zFarMax] band and the ray's
//    depth over the step as a white segment: where the segment enters the band, the ray may
//    be blocked there.
void drawPlot(const std::vector<RayStepRecord>& steps) {
  const ImVec2 size{ImGui::GetContentRegionAvail().x, uiPixels(140)};
  const ImVec2 at = ImGui::GetCursorScreenPos();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(at, {at.x + size.x, at.y + size.y}, IM_COL32(20, 20, 24, 255));
  float low = 1, high = 0;
  for (const RayStepRecord& s : steps) {
    low = std::min({low, s.rayDepthEnter, s.rayDepthExit});
    high = std::max({high, s.rayDepthEnter, s.rayDepthExit});
    if (s.level >= 0 && s.zNearMin <= s.zFarMax) {
      low = std::min(low, s.zNearMin);
      high = std::max(high, s.zFarMax);
    }
  }
  if (high <= low) high = low + 1;
  const auto y = [&](float depth) { return at.y + 4 + (depth - low) / (high - low) * (size.y - 8); };
  const float column = size.x / float(std::max<size_t>(steps.size(), 1));
  for (size_t i = 0; i < steps.size(); ++i) {
    const RayStepRecord& s = steps[i];
    const float x0 = at.x + column * float(i), x1 = x0 + column;
    const ImU32 color = levelColor(s.level);
    if (s.level >= 0 && s.zNearMin <= s.zFarMax) {
      draw->AddRectFilled({x0 + 1, y(s.zNearMin)}, {x1 - 1, y(s.zFarMax)}, (color & 0x00ffffff) | 0x60000000);
      draw->AddRect({x0 + 1, y(s.zNearMin)}, {x1 - 1, y(s.zFarMax)}, color);
    }
    draw->AddLine({x0, y(s.rayDepthEnter)}, {x1, y(s.rayDepthExit)}, IM_COL32_WHITE, 2);
  }
  ImGui::Dummy(size);
  ImGui::PushTextWrapPos(0);
  ImGui::TextDisabled("x: step; y: light depth (down: farther). Bands: zNearMin..zFarMax of "
                      "the visited window, coloured by level; white: the ray's depth.");
  ImGui::PopTextWrapPos();
}

// 2. The step table (s: stepping at the step's end).
void drawTable(const std::vector<RayStepRecord>& steps) {
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY | ImGuiTableFlags_ScrollX |
                                ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit;
  if (!ImGui::BeginTable("steps", 7, flags, {0, uiPixels(200)})) return;
  ImGui::TableSetupScrollFreeze(0, 1);
  for (const char* name : {"#", "lvl", "window", "s", "ray depth", "zNearMin..zFarMax", "decision"})
    ImGui::TableSetupColumn(name);
  ImGui::TableHeadersRow();
  for (size_t i = 0; i < steps.size(); ++i) {
    const RayStepRecord& s = steps[i];
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::Text("%zu", i);
    ImGui::TableNextColumn();
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(levelColor(s.level)), "%d", s.level);
    ImGui::TableNextColumn();
    ImGui::Text("%d,%d-%d,%d", s.windowLo.x, s.windowLo.y, s.windowHi.x, s.windowHi.y);
    ImGui::TableNextColumn();
    if (s.stepping >= 0) ImGui::Text("%.4f", s.stepping);
    ImGui::TableNextColumn();
    ImGui::Text("%.4f-%.4f", s.rayDepthEnter, s.rayDepthExit);
    ImGui::TableNextColumn();
    ImGui::Text("%.4f..%.4f", s.zNearMin, s.zFarMax);
    ImGui::TableNextColumn();
    if (s.point) ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(pointColor(s)), "%s", s.decision.c_str());
    else ImGui::TextUnformatted(s.decision.c_str());
  }
  ImGui::EndTable();
}

}  // namespace

// 3. Summary, plot, table; the visited windows become rectangles over light-sized views.
void drawRayTracePanel(const RayTraceInfo& trace, glm::ivec2 lightMapSize,
                       std::vector<ViewOverlayShape>& overlay) {
  ImGui::TextWrapped("%zu steps%s%s", trace.steps.size(), trace.result.empty() ? "" : ", ",
                     trace.result.c_str());
  if (!trace.commandLine.empty()) {
    ImGui::TextDisabled("CLI:");
    ImGui::SameLine();
    ImGui::TextWrapped("%s", trace.commandLine.c_str());
    if (ImGui::SmallButton("Copy command")) ImGui::SetClipboardText(trace.commandLine.c_str());
    if (!trace.commandNote.empty()) ImGui::TextWrapped("%s", trace.commandNote.c_str());
  }
  if (trace.steps.empty()) return;
  const std::vector<ViewOverlayShape> shapes = traceOverlay(trace, lightMapSize);
  overlay.insert(overlay.end(), shapes.begin(), shapes.end());
  if (hasPoints(trace.steps)) drawPointPlot(trace.steps);
  else drawPlot(trace.steps);
  drawTable(trace.steps);
}

void describeTraceCommand(const UiState& state, RayTraceInfo& trace) {
  trace.commandLine.clear();
  trace.commandNote.clear();
  const Session& session = state.session;
  if (!session.frame || !state.views.pick) return;
  const int width = session.frame->eyeWidth, height = session.frame->eyeHeight;
  const glm::ivec2 image{state.views.pick->x, height - 1 - state.views.pick->y};  // row 0 on top
  std::vector<std::string> sets;
  for (const auto& stage : session.pipeline.stages())
    for (const Param& param : stage->params()) {
      const std::string key = stage->name() + "." + param.key;
      // The window sets the picks itself (record_*, pick_*, patch_*): the command's --pixel
      // says which pixel, and auto parameters are auto on the command line too.
      const bool pick = param.key.rfind("record_", 0) == 0 || param.key.rfind("pick_", 0) == 0 ||
                        param.key.rfind("patch_", 0) == 0;
      if (pick || param.automatic) continue;
      const auto declared = session.parameterDefaults.find(key);
      if (!param.allowsAuto && declared != session.parameterDefaults.end() &&
          declared->second == param.value)
        continue;
      sets.push_back(key + "=" + param.toString());
    }
  trace.commandLine = traceCommandLine(session.sceneSource, image.x, image.y, width, height, sets,
                                       session.time);
  const Camera& c = session.scene.camera;
  const Camera& c0 = session.initialCamera;
  const AreaLight& l = session.scene.light;
  const AreaLight& l0 = session.initialLight;
  if (c.position != c0.position || c.target != c0.target || c.up != c0.up ||
      c.fovYDegrees != c0.fovYDegrees || l.center != l0.center || l.forward != l0.forward ||
      l.up != l0.up || l.width != l0.width || l.height != l0.height)
    trace.commandNote = "The camera or the light moved since the scene loaded; the command "
                        "uses the scene's (Reset camera / Reset light to match).";
}
