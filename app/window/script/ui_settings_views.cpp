#include "window/script/ui_settings_views.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "base/input_error.h"
#include "base/json_input.h"
#include "window/ui_scale.h"
#include "window/ui_state.h"

using nlohmann::json;

namespace {

[[noreturn]] void fail(const std::string& pointer, const std::string& what) {
  throw std::invalid_argument(pointer + ": " + what);
}

float finite(const json& value, const std::string& pointer) {
  if (!value.is_number() || !std::isfinite(value.get<double>())) fail(pointer, "expected a finite number");
  return value.get<float>();
}

void onlyKeys(const json& object, const std::string& pointer, const std::vector<std::string>& keys) {
  if (!object.is_object()) fail(pointer, "expected an object");
  for (const auto& [key, value] : object.items())
    if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
      std::string valid;
      for (const std::string& allowed : keys) valid += (valid.empty() ? "" : ", ") + allowed;
      fail(jsonPointer(pointer, key), "unknown key; valid: " + valid);
    }
}

// What one view panel keeps (the transform's texture size: see the header).
struct PanelSettings {
  std::string output, minus;
  bool clipNegative = false, locked = false, fit = true;
  ViewSettings settings;
  ViewTransform transform;
  glm::ivec2 texture{0, 0};
};

json panelJson(const ViewPanel& view) {
  std::string channels;
  for (int c = 0; c < 4; ++c)
    if (view.settings.channels[size_t(c)]) channels += "RGBA"[c];
  const glm::vec2 center = view.transform.center;
  return {{"output", view.output}, {"minus", view.minus}, {"clip_negative", view.clipNegative},
          {"locked", view.locked}, {"level", view.settings.layer},
          {"zoom", view.fitted || view.fitPending ? json("fit") : json(view.transform.zoom)},
          {"center", {center.x, center.y}},
          {"texture", {view.lastTextureSize.x, view.lastTextureSize.y}},
          {"colormap", colormapName(view.settings.colormap)}, {"channels", channels},
          {"range", {view.settings.black, view.settings.white}}, {"auto_range", view.settings.autoRange},
          {"overlay", view.settings.overlay}};
}

// 1. One panel, checked against the pipeline's outputs.
PanelSettings readPanel(const UiState& state, const json& p, const std::string& at) {
  onlyKeys(p, at, {"output", "minus", "clip_negative", "locked", "level", "zoom", "center", "texture",
                   "colormap", "channels", "range", "auto_range", "overlay"});
  PanelSettings panel;
  auto output = [&](const char* key) -> std::string {
    if (!p.contains(key)) return "";
    if (!p[key].is_string()) fail(at + "/" + key, "expected \"stage.output\"");
    const std::string name = p[key].get<std::string>();
    if (!name.empty() && !state.session.outputOf(name))
      fail(at + "/" + key, "unknown output '" + printable(name) + "'; valid: " + [&] {
        std::string all;
        for (const std::string& k : state.session.outputKeys()) all += (all.empty() ? "" : ", ") + k;
        return all;
      }());
    return name;
  };
  auto flag = [&](const char* key, bool& target) {
    if (!p.contains(key)) return;
    if (!p[key].is_boolean()) fail(at + "/" + key, "expected true or false");
    target = p[key].get<bool>();
  };
  panel.output = output("output");
  panel.minus = output("minus");
  flag("clip_negative", panel.clipNegative);
  flag("locked", panel.locked);
  flag("overlay", panel.settings.overlay);
  if (p.contains("level")) {
    if (!p["level"].is_number_integer() || p["level"].get<int>() < 0) fail(at + "/level", "expected an integer >= 0");
    panel.settings.layer = p["level"].get<int>();
  }
  if (p.contains("zoom") && p["zoom"] != "fit") {
    const float zoom = finite(p["zoom"], at + "/zoom");
    if (zoom < kMinZoom || zoom > kMaxZoom)
      fail(at + "/zoom", "expected \"fit\" or a zoom in [" + std::to_string(kMinZoom) + ", " + std::to_string(kMaxZoom) + "]");
    panel.fit = false;
    panel.transform.zoom = zoom;
  }
  if (p.contains("center")) {
    if (!p["center"].is_array() || p["center"].size() != 2) fail(at + "/center", "expected [x, y]");
    panel.transform.center = {finite(p["center"][0], at + "/center/0"), finite(p["center"][1], at + "/center/1")};
  }
  if (p.contains("texture")) {
    const json& t = p["texture"];
    if (!t.is_array() || t.size() != 2 || !t[0].is_number_integer() || !t[1].is_number_integer() ||
        t[0].get<int>() < 0 || t[1].get<int>() < 0)
      fail(at + "/texture", "expected [width, height], integers >= 0");
    panel.texture = {t[0].get<int>(), t[1].get<int>()};
  }
  if (p.contains("colormap")) {
    const std::vector<std::string> names = colormapNames();
    const auto it = std::find(names.begin(), names.end(), p["colormap"]);
    if (it == names.end()) fail(at + "/colormap", "expected gray, perceptual, diverging or categorical");
    panel.settings.colormap = Colormap(it - names.begin());
  }
  if (p.contains("channels")) {
    const std::string letters = p["channels"].is_string() ? p["channels"].get<std::string>() : "?";
    if (letters.find_first_not_of("RGBA") != std::string::npos) fail(at + "/channels", "expected letters from RGBA");
    for (int c = 0; c < 4; ++c) panel.settings.channels[size_t(c)] = letters.find("RGBA"[c]) != std::string::npos;
  }
  if (p.contains("range")) {
    if (!p["range"].is_array() || p["range"].size() != 2) fail(at + "/range", "expected [black, white]");
    panel.settings.black = finite(p["range"][0], at + "/range/0");
    panel.settings.white = finite(p["range"][1], at + "/range/1");
    panel.settings.autoRange = false;
  }
  if (p.contains("auto_range")) {  // after "range": the saved range is the last one found
    if (!p["auto_range"].is_boolean()) fail(at + "/auto_range", "expected true or false");
    panel.settings.autoRange = p["auto_range"].get<bool>();
  }
  return panel;
}

// 2. Commits one panel: its settings stay (not re-initialised from the output's default).
void applyPanel(ViewPanel& view, const PanelSettings& panel) {
  view.output = panel.output;
  view.minus = panel.minus;
  view.clipNegative = panel.clipNegative;
  view.locked = panel.locked;
  view.settings = panel.settings;
  view.settingsFor = panel.output;
  view.autofitPending = false;
  view.fitPending = panel.fit;
  view.fitted = panel.fit;
  if (!panel.fit) {
    view.transform = panel.transform;
    view.lastTextureSize = panel.texture;  // placeImage rescales to the texture shown
  }
}

}  // namespace

json uiScaleJson(const UiState& state) { return state.uiScale; }

json viewsJson(const UiState& state) {
  const ViewState& views = state.views;
  json panels = json::array();
  for (int v = 0; v < views.shownViews(); ++v) panels.push_back(panelJson(views.panels[v]));
  return {{"layout", layoutName(views.layout)}, {"active", views.activeView}, {"linked", views.linked},
          {"side_panel", state.showSpeedError ? "speed_error" : "inspector"}, {"panels", panels}};
}

std::function<void(UiState&)> readUiScale(const UiState&, const json& value, const std::string& pointer) {
  const float scale = finite(value, pointer);
  if (!validUiScale(scale))
    fail(pointer, "expected a UI scale in [" + std::to_string(kMinUiScale) + ", " + std::to_string(kMaxUiScale) + "]");
  return [scale](UiState& state) { state.uiScale = scale; };
}

std::function<void(UiState&)> readViews(const UiState& state, const json& value, const std::string& pointer) {
  onlyKeys(value, pointer, {"layout", "active", "linked", "side_panel", "panels"});
  ViewLayout layout = state.views.layout;
  if (value.contains("layout") &&
      !(value["layout"].is_string() && layoutFromName(value["layout"].get<std::string>(), layout)))
    fail(pointer + "/layout", "expected one, side_by_side or grid");
  ViewState shape;  // only for shownViews() of the new layout
  shape.layout = layout;
  int active = 0;
  if (value.contains("active")) {
    if (!value["active"].is_number_integer() || value["active"].get<int>() < 0 ||
        value["active"].get<int>() >= shape.shownViews())
      fail(pointer + "/active", "expected a view shown by the layout, 0 to " + std::to_string(shape.shownViews() - 1));
    active = value["active"].get<int>();
  }
  bool linked = state.views.linked, speedError = state.showSpeedError;
  if (value.contains("linked")) {
    if (!value["linked"].is_boolean()) fail(pointer + "/linked", "expected true or false");
    linked = value["linked"].get<bool>();
  }
  if (value.contains("side_panel")) {
    if (value["side_panel"] != "inspector" && value["side_panel"] != "speed_error")
      fail(pointer + "/side_panel", "expected inspector or speed_error");
    speedError = value["side_panel"] == "speed_error";
  }
  std::vector<PanelSettings> panels;
  if (value.contains("panels")) {
    const json& list = value["panels"];
    if (!list.is_array() || list.size() > size_t(kMaxViews)) fail(pointer + "/panels", "expected an array of at most 4 views");
    for (size_t i = 0; i < list.size(); ++i)
      panels.push_back(readPanel(state, list[i], pointer + "/panels/" + std::to_string(i)));
  }
  return [=](UiState& target) {
    for (size_t i = 0; i < panels.size(); ++i) applyPanel(target.views.panels[i], panels[i]);
    target.views.setLayout(layout);
    target.views.activeView = active;
    target.views.linked = linked;
    target.showSpeedError = speedError;
  };
}
