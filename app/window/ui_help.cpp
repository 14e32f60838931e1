#include "window/ui_help.h"

#include <imgui.h>

#include <algorithm>

#include "window/ui_state.h"

const Shortcut* shortcuts(int& count) {
  static const Shortcut list[] = {
      {"F1 or ?", "show / hide this help"},
      {"F5", "reload shaders (a failed compile keeps the last good one)"},
      {"Tab", "switch the active view (A / B / C / D)"},
      {"V", "show / hide the second view (A | B)"},
      {"G", "show / hide the 2x2 grid of views (compare four methods)"},
      {"L", "link / unlink zoom and pan of the views"},
      {"F", "fit the active view"},
      {"1", "one texel per screen pixel"},
      {"A", "autofit black / white to the visible texels"},
      {"R", "reset the view to the stage's declared display"},
      {"Arrow keys", "move the pick by one texel (Shift: 10)"},
      {"Ctrl+S", "save settings (penumbra_settings.json)"},
      {"Ctrl+E", "export all stages"},
      {"F12", "save a screenshot of the window"},
      {"Esc", "cancel a run under way (so does the Cancel button shown after 1 s)"},
      {"Ctrl+Q", "quit"},
      {"Wheel", "zoom the view about the cursor"},
      {"Left drag / click", "pan the view / pick a texel"},
      {"Right drag", "orbit the camera (the pipeline re-runs)"},
      {"Middle or Shift+right drag", "pan the camera"},
      {"Ctrl+wheel", "move the camera closer / farther"},
      {"Ctrl+click an output", "show it in the next view (opening B)"},
      {"Alt+drag (scene view)", "move the light over the ground (outline: yellow)"},
      {"Alt+Shift+drag", "raise / lower the light"},
      {"Alt+right drag", "turn the light (yaw, pitch)"},
      {"Alt+wheel", "scale the light (Shift: width only, Ctrl: height only)"},
      {"Space / N (lesson)", "next step of a lesson (penumbra lesson FILE)"},
  };
  count = int(sizeof list / sizeof list[0]);
  return list;
}

void drawHelpWindow(UiState& state) {
  if (!state.showHelp) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos({display.x * 0.5f, display.y * 0.5f}, ImGuiCond_Appearing, {0.5f, 0.5f});
  // 50 characters' widths, within the window at any UI scale; long lists scroll.
  ImGui::SetNextWindowSize({std::min(display.x * 0.9f, 50 * ImGui::GetFontSize()), 0}, ImGuiCond_Always);
  ImGui::SetNextWindowSizeConstraints({0, 0}, {display.x * 0.9f, display.y * 0.9f});
  if (ImGui::Begin("Help", &state.showHelp, ImGuiWindowFlags_NoCollapse)) {
    ImGui::TextWrapped("penumbra shows every stage of Curtis & Olano's Monte Carlo soft shadows. "
                       "Click an output on the left to view it; parameters re-run the pipeline.");
    if (ImGui::BeginTable("shortcuts", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
      int count = 0;
      const Shortcut* list = shortcuts(count);
      for (int i = 0; i < count; ++i) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextColored({0.95f, 0.8f, 0.4f, 1}, "%s", list[i].keys);
        ImGui::TableNextColumn();
        ImGui::TextWrapped("%s", list[i].action);
      }
      ImGui::EndTable();
    }
    ImGui::PushTextWrapPos(0);
    ImGui::TextDisabled("Coordinates are image coordinates: (0, 0) is the top-left texel, as in "
                        "the PNGs and `penumbra trace --pixel X,Y`.");
    // Measured in docs/classroom.md (the cube at 640x480, eye pixels of its top face).
    if (ImGui::CollapsingHeader("Why stripes of lit / penumbra in classify.mask?"))
      ImGui::TextUnformatted(
          "On a lit face (the cube's top) the stripes are Eq 3.3 itself, not a defect. The face "
          "lies in the near layer, so zNearMin over the region any ray can reach is the face's own "
          "depth at texel centres, up to about one texel's depth step shallower than the pixel. "
          "Whether a pixel passes z <= zNearMin (lit) depends on where it falls inside its texel, "
          "and that pattern beats against the pixel grid: moire. The test is conservative: the "
          "'penumbra' pixels are traced and every ray reaches the light (visibility 1), so only "
          "time is lost. Finer maps mark more of the face penumbra (the region spans more "
          "texels): 64% at 256, 76% at 512, 89% at 1024.");
    ImGui::PopTextWrapPos();
  }
  ImGui::End();
}

void drawShaderLogWindow(UiState& state) {
  if (!state.showShaderLog) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos({display.x * 0.5f, display.y * 0.3f}, ImGuiCond_Appearing, {0.5f, 0.0f});
  ImGui::SetNextWindowSize({display.x * 0.6f, display.y * 0.4f}, ImGuiCond_Appearing);
  if (ImGui::Begin("Shader log", &state.showShaderLog)) {
    ImGui::TextColored({1, 0.5f, 0.4f, 1}, "Hot reload failed; the last good programs are in use.");
    if (ImGui::Button("Retry (F5)")) state.reloadShaders();
    ImGui::Separator();
    ImGui::TextUnformatted(state.shaderLog.c_str());
  }
  ImGui::End();
}
