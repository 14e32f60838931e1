#include "window/ui_widgets.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <map>

#include "shared_inputs/light/auto_params.h"

// 1. The (?) marker.
void helpMarker(const std::string& text) {
  ImGui::SameLine();
  ImGui::TextDisabled("(?)");
  if (ImGui::IsItemHovered()) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
    ImGui::TextUnformatted(text.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  }
}

// 2. One widget per parameter type; Ctrl+click on a slider types a value. A name too long
//    for the line (narrow panel, large UI scale) goes on its own line above the widget.
std::optional<double> autoChosenValue(const std::string& stage, const Param& param, const Frame* frame) {
  if (!param.allowsAuto || !param.automatic || !frame) return {};
  const AutoSettings& chosen = lightAutoSettings(*frame);
  if (stage == "light" && param.key == "resolution") return effectiveResolution(param, chosen);
  if (stage == "light" && param.key == "layers") return double(chosen.layers - 1);  // options: one, two, three
  if (stage == "trace" && param.key == "rays") return effectiveRays(param, chosen);
  const auto counter = [&](const char* name) -> std::optional<double> {  // chosen during the run
    const auto found = frame->counters.find(name);
    if (found == frame->counters.end()) return {};
    return found->second;
  };
  if (stage == "light" && param.key == "fov_degrees") return counter("auto.fov_degrees");
  if (stage == "ssm" && param.key == "resolution") return counter("auto.ssm_resolution");
  if (param.type == Param::Type::Enum) return param.value;  // decided by the pipeline, in place
  return {};
}

double shownParamValue(const Param& param, std::optional<double> autoValue) {
  return param.automatic && autoValue ? *autoValue : param.value;
}

bool drawParam(Param& param, ParamHandValues& handValues, std::optional<double> autoValue) {
  bool changed = false;
  // `auto` (stages/shared_inputs/light/auto_settings.h): a checkbox before the widget, which is then greyed.
  const ImGuiStyle& style = ImGui::GetStyle();
  const float autoWidth = param.allowsAuto ? ImGui::GetFrameHeight() + style.ItemInnerSpacing.x +
                                                 ImGui::CalcTextSize("auto").x + style.ItemSpacing.x
                                           : 0.0f;
  const float nameWidth = ImGui::CalcTextSize(param.key.c_str()).x + style.ItemInnerSpacing.x;
  const bool nameAbove = param.type != Param::Type::Bool &&
                         autoWidth + ImGui::CalcItemWidth() + nameWidth + buttonsWidth({"(?)"}) >
                             ImGui::GetContentRegionAvail().x;
  const std::string hidden = "##" + param.key;
  if (nameAbove) ImGui::TextUnformatted(param.key.c_str());
  // A choice the pipeline decides writes it into the value: the hand value is kept in
  // `handValues` while auto is on, so that unticking gives it back.
  if (param.allowsAuto) {
    bool automatic = param.automatic;
    if (ImGui::Checkbox(("auto##" + param.key).c_str(), &automatic)) {
      if (automatic) handValues[&param] = param.value;
      else if (const auto hand = handValues.find(&param); hand != handValues.end()) param.value = hand->second;
      param.automatic = automatic;
      changed = true;
    }
    ImGui::SameLine();
  }
  if (nameAbove) ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - buttonsWidth({"(?)"}));
  const char* label = nameAbove ? hidden.c_str() : param.key.c_str();
  const bool showsChoice = param.automatic && autoValue.has_value();
  const double shown = shownParamValue(param, autoValue);
  ImGui::BeginDisabled(param.automatic);
  switch (param.type) {
    case Param::Type::Bool: {
      bool value = shown != 0;
      if (ImGui::Checkbox(label, &value)) param.value = value, changed = true;
      break;
    }
    case Param::Type::Int: {
      int value = int(shown);
      if (ImGui::SliderInt(label, &value, int(param.min), int(param.max), showsChoice ? "%d (auto)" : "%d")) {
        param.value = std::clamp(value, int(param.min), int(param.max));
        changed = true;
      }
      break;
    }
    case Param::Type::Float: {
      float value = float(shown);
      const bool wide = param.min > 0 && param.max / param.min >= 100;
      if (ImGui::SliderFloat(label, &value, float(param.min), float(param.max), showsChoice ? "%.4g (auto)" : "%.4g",
                             wide ? ImGuiSliderFlags_Logarithmic : 0)) {
        param.value = std::clamp(double(value), param.min, param.max);
        changed = true;
      }
      break;
    }
    case Param::Type::Enum: {
      const int value = int(shown);
      const std::string preview = size_t(value) < param.options.size()
                                      ? param.options[size_t(value)] + (showsChoice ? " (auto)" : "")
                                      : std::string("?");
      if (ImGui::BeginCombo(label, preview.c_str())) {
        for (size_t i = 0; i < param.options.size(); ++i)
          if (ImGui::Selectable(param.options[i].c_str(), value == int(i))) {
            param.value = double(i);
            changed = true;
          }
        ImGui::EndCombo();
      }
      break;
    }
  }
  ImGui::EndDisabled();
  helpMarker(param.doc + "\nRange: " + param.rangeText() + "\nCtrl+click a slider to type." +
             (param.allowsAuto ? "\nUnder auto the control shows what auto chose, greyed; unticked, the value set by hand." : ""));
  return changed;
}

// 3. Names of the formats stages declare.
const char* formatName(GLenum format) {
  switch (format) {
    case GL_RGBA32F: return "RGBA32F";
    case GL_RGBA16F: return "RGBA16F";
    case GL_RG32F: return "RG32F";
    case GL_R32F: return "R32F";
    case GL_RGBA8: return "RGBA8";
    case GL_R32UI: return "R32UI";
    case GL_RG32UI: return "RG32UI";
    case GL_RGBA32UI: return "RGBA32UI";
    case GL_R8UI: return "R8UI";
    case GL_DEPTH_COMPONENT32F: return "DEPTH32F";
    case kBufferFormat: return "buffer";
    default: return "?";
  }
}

// 4. Toolbar wrapping.
float uiPixels(float pixelsAtScale1) { return pixelsAtScale1 * ImGui::GetFontSize() / 13.0f; }

float buttonsWidth(std::initializer_list<const char*> labels) {
  const ImGuiStyle& style = ImGui::GetStyle();
  float width = 0;
  for (const char* label : labels)
    width += ImGui::CalcTextSize(label, nullptr, true).x + 2 * style.FramePadding.x + style.ItemSpacing.x;
  return width;
}

void sameLineIfButtonsFit(std::initializer_list<const char*> labels) {
  const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
  ImGui::SameLine();
  if (ImGui::GetCursorScreenPos().x + buttonsWidth(labels) > right) ImGui::NewLine();
}

void sameLineIfFits(float width) {
  width = uiPixels(width);
  const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
  ImGui::SameLine();
  if (ImGui::GetCursorScreenPos().x + width > right) ImGui::NewLine();
}

void textPieces(const std::vector<std::string>& pieces) {
  const float avail = ImGui::GetContentRegionAvail().x, gap = ImGui::CalcTextSize("  ").x;
  float used = 0;
  for (const std::string& piece : pieces) {
    const float width = ImGui::CalcTextSize(piece.c_str()).x;
    const size_t space = piece.find(' ');
    if (width > avail && space != std::string::npos) {  // alone too wide: its words on lines of their own
      if (used > 0) ImGui::NewLine();
      textPieces({piece.substr(0, space)});
      textPieces({piece.substr(space + 1)});
      used = 0;
      continue;
    }
    if (used > 0 && used + gap + width <= avail) {
      ImGui::SameLine(0, gap);
      used += gap + width;
    } else {
      used = width;
    }
    ImGui::TextUnformatted(piece.c_str());
  }
}

void hintText(const std::string& text) {
  ImGui::PushTextWrapPos(0);
  ImGui::TextDisabled("%s", text.c_str());
  ImGui::PopTextWrapPos();
}

std::string timingText(const StageTime& time) {
  if (!time.ran) return "not run: no output the window shows depends on it";
  char text[160];
  std::snprintf(text, sizeof text,
                "last run %.2f ms; median %.2f ms over %d run(s) with these parameters, scene "
                "and eye size (any change starts a new series)",
                time.milliseconds, time.median, time.runs);
  return text;
}

std::string comboPreview(const std::string& name, float comboWidth) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float room = comboWidth - ImGui::GetFrameHeight() - 2 * style.FramePadding.x;
  const auto fits = [&](const std::string& text) { return ImGui::CalcTextSize(text.c_str()).x <= room; };
  if (fits(name)) return name;
  const size_t dot = name.find('.');
  if (dot != std::string::npos)
    for (size_t keep = dot; keep-- > 1;) {  // at least one letter of the stage
      const std::string text = name.substr(0, keep) + "..." + name.substr(dot + 1);
      if (fits(text)) return text;
    }
  for (size_t keep = name.size(); keep-- > 1;) {
    const std::string text = name.substr(0, keep) + "...";
    if (fits(text)) return text;
  }
  return "...";
}
