#include "window/panels/ui_scene_panel.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>
#include <initializer_list>
#include <string>
#include <vector>

#include "scene/scene_builtin.h"
#include "scene/scene_frame.h"
#include "window/ui_camera.h"
#include "window/panels/ui_export.h"
#include "window/ui_export_progress.h"
#include "window/script/ui_script_actions.h"
#include "window/script/ui_settings.h"
#include "window/ui_state.h"
#include "window/ui_widgets.h"

namespace {

// 1. Scene: built-ins in a combo, or a typed path to a scene JSON / glTF.
void drawScenePicker(UiState& state) {
  std::string& path = state.panelMemory.scenePath;
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.4f);  // room for "91216 tris"
  if (ImGui::BeginCombo("scene", state.session.scene.name.c_str())) {
    for (const std::string& name : builtinSceneNames())
      if (ImGui::Selectable(name.c_str(), name == state.session.sceneSource))
        if (std::string problem = state.loadScene(name); !problem.empty()) state.status = problem;
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  ImGui::TextDisabled("%zu tris", state.session.scene.triangleCount());
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - buttonsWidth({"Load"}));
  const bool entered = ImGui::InputTextWithHint("##scenepath", ".json / .gltf / .glb path", &path,
                                                ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::SameLine();
  if ((ImGui::Button("Load") || entered) && !path.empty())
    if (std::string problem = state.loadScene(path); !problem.empty()) state.status = problem;
  // The model's size in the scene's units, and a button that fits camera, ground and light.
  // In pieces ("x [a, b]", "y [...]", ...) that never break inside a number.
  std::vector<std::string> pieces{"bounds"};
  const std::string bounds = boundsText(state.session.scene.bounds(false));
  for (size_t start = 0; start < bounds.size();) {
    const size_t end = bounds.find("] ", start);
    pieces.push_back(bounds.substr(start, end == std::string::npos ? std::string::npos : end + 1 - start));
    start = end == std::string::npos ? bounds.size() : end + 2;
  }
  textPieces(pieces);
  if (ImGui::Button("Frame scene"))
    if (std::string problem = frameLoadedScene(state); !problem.empty()) state.status = problem;
  helpMarker("Places the camera, the ground and the light to fit the model, whatever its units: "
             "the camera outside it looking at its centre, the ground under its lowest point, "
             "the light above it (a bare .gltf/.glb is framed when it loads).");
}

// 2. Eye image size: follow the view, or a fixed size (the performance target is 640x480).
void drawEyeSize(UiState& state) {
  static const int sizes[][2] = {{320, 240}, {640, 480}, {512, 512}, {1024, 768}, {1280, 720}};
  char current[32];
  std::snprintf(current, sizeof current, "%dx%d", state.session.eye.width, state.session.eye.height);
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
  if (ImGui::BeginCombo("eye size", state.session.eye.fitView ? "fit view" : current)) {
    if (ImGui::Selectable("fit view", state.session.eye.fitView)) state.session.eye.fitView = true;
    for (const auto& size : sizes) {
      std::snprintf(current, sizeof current, "%dx%d", size[0], size[1]);
      if (ImGui::Selectable(current, !state.session.eye.fitView && state.session.eye.width == size[0] &&
                                         state.session.eye.height == size[1]))
        state.session.eye = {false, size[0], size[1]};
    }
    ImGui::EndCombo();
  }
  helpMarker("The eye image (G-buffer and everything per pixel). 'fit view': one texel per "
             "screen pixel of view A.");
}

// 3a. Three numbers (a point): each field must hold "-00.00"; where the shared control
//     width is too narrow for three (a large UI scale), the name goes above and the fields
//     take the whole line.
bool dragTriplet(const char* label, float* values) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float needed = 3 * (ImGui::CalcTextSize("-00.00").x + 2 * style.FramePadding.x) + 2 * style.ItemInnerSpacing.x;
  if (ImGui::CalcItemWidth() >= needed) return ImGui::DragFloat3(label, values, 0.02f, 0, 0, "%.2f");
  ImGui::TextUnformatted(label);
  ImGui::SetNextItemWidth(std::max(ImGui::GetContentRegionAvail().x - buttonsWidth({"(?)"}), needed));
  return ImGui::DragFloat3((std::string("##") + label).c_str(), values, 0.02f, 0, 0, "%.2f");
}

// 3. Camera and light: numbers and sliders (the mouse in a view orbits the camera too).
void drawCameraAndLight(UiState& state) {
  Camera& camera = state.session.scene.camera;
  AreaLight& light = state.session.scene.light;
  const Camera cameraBefore = camera;
  const AreaLight lightBefore = light;
  bool changed = false;
  changed |= dragTriplet("eye", &camera.position.x);
  changed |= dragTriplet("target", &camera.target.x);
  changed |= ImGui::SliderFloat("fov y", &camera.fovYDegrees, 10, 120, "%.0f deg");
  changed |= dragTriplet("light", &light.center.x);
  helpMarker("Centre of the rectangular area light (world units). In a scene view (any "
             "eye-sized output): Alt+drag moves the light over the ground, Alt+Shift+drag "
             "raises / lowers it, Alt+right drag turns it, Alt+wheel scales it (Shift: width, "
             "Ctrl: height). Zoom the view out (wheel) to see a light above the picture.");
  float yaw = 0, pitch = 0;
  lightAngles(light, yaw, pitch);
  bool turned = ImGui::SliderFloat("light yaw", &yaw, -180, 180, "%.0f deg");
  turned |= ImGui::SliderFloat("light pitch", &pitch, -90, 0, "%.0f deg");
  helpMarker("Direction the light faces; pitch -90 points straight down.");
  if (turned) setLightAngles(light, yaw, pitch);
  changed |= turned;
  changed |= ImGui::SliderFloat("light width", &light.width, 0.02f, 6, "%.2f", ImGuiSliderFlags_Logarithmic);
  changed |= ImGui::SliderFloat("light height", &light.height, 0.02f, 6, "%.2f", ImGuiSliderFlags_Logarithmic);
  helpMarker("Light size: the penumbra widens with it (thesis §3.1). Ctrl+click to type; "
             "Alt+wheel over a scene view scales it (Shift: width only, Ctrl: height only).");
  light.width = std::max(light.width, 1e-3f);
  light.height = std::max(light.height, 1e-3f);
  if (changed && !validateScene(state.session.scene).empty()) {  // never hand the pipeline a broken scene
    camera = cameraBefore;
    light = lightBefore;
  }
  if (ImGui::Button("Reset camera")) camera = state.session.initialCamera;
  sameLineIfButtonsFit({"Reset light"});
  if (ImGui::Button("Reset light")) light = state.session.initialLight;
  sameLineIfButtonsFit({"[x] outline", "(?)"});  // a checkbox: its box counts as "[x] "
  ImGui::Checkbox("outline", &state.views.showLight);
  helpMarker("Draw the light rectangle (yellow), its centre and its axis down to the ground "
             "over the scene views; hold Alt over a view to drag it.");
}

// 4a. A path field with buttons after it: on the buttons' line when its text (or hint) fits
//     there, else on a line of its own above them.
void pathField(const char* id, std::string& path, const char* hint, std::initializer_list<const char*> buttons) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float text = ImGui::CalcTextSize((path.empty() ? hint : path.c_str())).x + 2 * style.FramePadding.x + 1;
  const float beside = ImGui::GetContentRegionAvail().x - buttonsWidth(buttons);
  const bool ownLine = text > beside;
  ImGui::SetNextItemWidth(ownLine ? ImGui::GetContentRegionAvail().x : beside);
  ImGui::InputTextWithHint(id, hint, &path);
  if (!ownLine) ImGui::SameLine();
}

// 4. Files and tools: settings, shaders, export all, how the pipeline re-runs.
void drawTools(UiState& state) {
  std::string& settingsPath = state.panelMemory.settingsPath;
  std::string& exportDirectory = state.panelMemory.exportDirectory;
  pathField("##settings", settingsPath, "", {"Save", "Load", "(?)"});
  if (ImGui::Button("Save")) {
    const std::string result = saveSettingsFile(state, settingsPath);
    state.reportResult("settings", result, result.rfind("saved ", 0) == 0);
  }
  ImGui::SameLine();
  if (ImGui::Button("Load##settings")) {
    bool ok = false;
    const std::string result = loadSettingsFile(state, settingsPath, ok);
    state.reportResult("settings", result, ok);
  }
  helpMarker("Settings JSON: scene, eye size, camera, light, every parameter. "
             "Open one at start with `penumbra --config FILE`.");
  pathField("##exportdir", exportDirectory, kDefaultExportDirectory, {"Export all", "(?)"});
  if (ImGui::Button("Export all")) requestExportAll(state, exportDirectory);  // between frames: its progress shows
  helpMarker("Every stage output (EXR raw + PNG) and run.json: the same files as "
             "`penumbra export` with these settings.");
  if (ImGui::Button("Reload shaders (F5)")) state.reloadShaders();
  sameLineIfButtonsFit({"[x] every frame", "(?)"});
  ImGui::Checkbox("every frame", &state.session.runEveryFrame);
  helpMarker("Re-run the pipeline every frame (for timing). Off: only when something changes.");
  // Steps, not a slider: the font atlas is rebuilt once per choice, not under a drag.
  static const float kScales[] = {0.75f, 1.0f, 1.25f, 1.5f, 1.75f, 2.0f, 2.5f, 3.0f};
  char current[16];
  std::snprintf(current, sizeof current, "%.2gx", state.uiScale);
  ImGui::SetNextItemWidth(uiPixels(80));
  if (ImGui::BeginCombo("UI scale", current)) {
    for (float scale : kScales) {
      char label[16];
      std::snprintf(label, sizeof label, "%.2gx", scale);
      if (ImGui::Selectable(label, scale == state.uiScale)) state.uiScale = scale;
    }
    ImGui::EndCombo();
  }
  helpMarker("Text and widget size, for projectors and high-DPI screens (the font is re-rasterised "
             "at the new size, so text stays sharp). Saved with the settings.");
}

}  // namespace

// 5. Sections.
void drawScenePanel(UiState& state) {
  if (!ImGui::CollapsingHeader("Scene, camera, light", ImGuiTreeNodeFlags_DefaultOpen)) return;
  // Controls share one width, leaving room for the longest label ("light height") and (?).
  const float avail = ImGui::GetContentRegionAvail().x;
  const float rest = avail - ImGui::CalcTextSize("light height").x - buttonsWidth({"(?)"}) -
                     ImGui::GetStyle().ItemInnerSpacing.x;
  ImGui::PushItemWidth(std::clamp(rest, 0.3f * avail, 0.62f * avail));
  drawScenePicker(state);
  drawEyeSize(state);
  drawCameraAndLight(state);
  ImGui::PopItemWidth();
  drawTools(state);
  ImGui::Separator();
}
