#include "window/ui_status_line.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "window/ui_layout.h"
#include "window/ui_log_panel.h"
#include "window/ui_state.h"

// The status line: the log's count, what happened last (scene warnings first), and how
//    fast things are on the right. The left text is cut with "..." before the right text
//    (hover: all of it); the log holds every warning and error whole.
void drawStatusLine(UiState& state, const Layout& layout) {
  ImGui::SetNextWindowPos({0, layout.panelHeight()});
  ImGui::SetNextWindowSize({layout.width, layout.status});
  ImGui::Begin("##status", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                        ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoTitleBar |
                                        ImGuiWindowFlags_NoScrollbar);
  const Session& session = state.session;
  const int eyeWidth = session.frame ? session.frame->eyeWidth : 0;
  const int eyeHeight = session.frame ? session.frame->eyeHeight : 0;
  char speed[200];
  const double pipelineMs = session.medianPipelineMs();
  std::snprintf(speed, sizeof speed, "eye %dx%d | pipeline %.1f ms (%.1f/s, median of %d) | UI %.0f fps | %s%s",
                eyeWidth, eyeHeight, pipelineMs, pipelineMs > 0 ? 1000.0 / pipelineMs : 0.0,
                session.medianRuns(), session.framesPerSecond(),
                session.runEveryFrame ? "runs every frame" : "runs on change",
                session.previewing && session.previewDivisor > 1
                    ? (" | PREVIEW at 1/" + std::to_string(session.previewDivisor) +
                       " resolution while the camera or the timeline moves").c_str()
                    : "");
  float speedWidth = ImGui::CalcTextSize(speed).x;
  if (speedWidth > 0.55f * layout.width) {  // large UI scale: the numbers only
    std::snprintf(speed, sizeof speed, "eye %dx%d | %.1f ms | UI %.0f fps%s", eyeWidth, eyeHeight,
                  pipelineMs, session.framesPerSecond(), session.previewing ? " | PREVIEW" : "");
    speedWidth = ImGui::CalcTextSize(speed).x;
  }
  const ImGuiStyle& style = ImGui::GetStyle();
  const float rightStart = layout.width - speedWidth - style.WindowPadding.x;
  drawLogCount(state);
  // What is left between the count and the right text, less a gap that keeps them apart.
  const float room = rightStart - 2 * style.ItemSpacing.x - ImGui::GetCursorScreenPos().x;
  std::string warning;
  if (!state.sceneWarnings.empty())  // what the depth-map methods cannot show (scene_checks.h)
    warning = "warning: " + state.sceneWarnings.front() +
              (state.sceneWarnings.size() > 1 ? " (+" + std::to_string(state.sceneWarnings.size() - 1) + " more)" : "");
  const std::string status = state.status.empty() ? "F1: help" : state.status;
  const float gap = style.ItemSpacing.x;
  const float statusWidth = ImGui::CalcTextSize(status.c_str()).x;
  const float warningWidth = warning.empty() ? 0 : ImGui::CalcTextSize(warning.c_str()).x + gap;
  // Both fit, or the warning keeps at least half of the room and the status the rest.
  float warningRoom = warningWidth;
  if (warningWidth + statusWidth > room) warningRoom = std::max(0.5f * room, room - statusWidth);
  const ImVec2 leftStart = ImGui::GetCursorScreenPos();
  if (!warning.empty()) {
    ImGui::TextColored({1.0f, 0.8f, 0.2f, 1.0f}, "%s", elided(warning, warningRoom - gap).c_str());
    ImGui::SameLine(0, gap);
  }
  const float statusRoom = room - (ImGui::GetCursorScreenPos().x - leftStart.x);
  const std::string shown = elided(status, statusRoom);
  if (state.statusIsProblem()) ImGui::TextColored({1.0f, 0.45f, 0.4f, 1.0f}, "%s", shown.c_str());
  else ImGui::TextUnformatted(shown.c_str());
  if (ImGui::IsMouseHoveringRect(leftStart, {rightStart, leftStart.y + layout.status})) {
    std::string all;
    for (const std::string& line : state.sceneWarnings) all += "warning: " + line + "\n";
    all += status;
    ImGui::SetNextWindowSize({std::min(layout.width * 0.8f, ImGui::CalcTextSize(all.c_str()).x + 2 * style.WindowPadding.x), 0});
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(0);
    ImGui::TextUnformatted(all.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  }
  ImGui::SameLine(rightStart);
  ImGui::TextUnformatted(speed);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("UI fps: frames the window draws per second while something happens\n"
                      "(1 / median time to build and draw one, over the last %d frames drawn\n"
                      "for input, a run or a script). Idle, it draws nothing: it wakes on input\n"
                      "or every 0.1 s and draws only what changed. %.0f such frames in the\n"
                      "last second.", session.framesMeasured(), session.framesDrawnPerSecond());
  ImGui::End();
}

