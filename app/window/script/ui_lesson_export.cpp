#include "window/script/ui_lesson_export.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include <imgui.h>
#include <imgui_internal.h>

#include "io/image_export.h"
#include "window/panels/ui_export.h"
#include "window/panels/ui_export_annotation.h"
#include "window/script/ui_lesson_crop.h"
#include "window/panels/ui_temporal.h"
#include "window/script/ui_lesson_numbers.h"
#include "window/ui_state.h"

namespace fs = std::filesystem;
using nlohmann::json;

// 1. Where a lesson's figures go.
std::string defaultLessonDirectory(const std::string& lessonPath) {
  return (fs::path(kDefaultExportDirectory) / fs::path(lessonPath).stem()).string();
}

std::string checkExportDirName(const json& value) {
  if (!value.is_string() || value.get<std::string>().empty()) return "expected a folder name";
  const fs::path path = value.get<std::string>();
  if (path.is_absolute()) return "expected a folder name under the output folder, not an absolute path";
  for (const fs::path& part : path)
    if (part == "..") return "expected a folder name under the output folder, without '..'";
  return "";
}

std::string checkExportView(const json& value) {
  if (value.is_string()) return "";
  if (!value.is_object() || !value.contains("file") || !value["file"].is_string())
    return "expected a file or folder name, or {\"file\": ..., \"caption\": ..., \"annotate\": ...}";
  for (const auto& [key, item] : value.items())
    if (key == "caption" ? !item.is_string()
        : key == "annotate" ? !item.is_boolean()
        : key != "file")
      return "\"" + key + "\": expected \"caption\" (a string) or \"annotate\" (true or false)";
  return "";
}

// 2. Numbers from the current run.
namespace {

bool stageMedian(const UiState& state, const std::string& stage, double& ms) {
  for (const StageTime& time : state.session.pipeline.lastTimes())
    if (time.stage == stage) {
      ms = time.ran ? time.median : 0;
      return time.ran;
    }
  return false;
}

std::string formatted(double value, const char* format) {
  char text[48];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

std::string number(const UiState& state, const ScriptContext& context, const std::string& name,
                   std::string& problem);

// A kept name's text or a number's, as a double (for pct: and ratio:).
bool operand(const UiState& state, const ScriptContext& context, const std::string& whole,
             const std::string& name, double& value, std::string& problem) {
  const auto kept = context.kept.find(name);
  const std::string text = kept != context.kept.end() ? kept->second : number(state, context, name, problem);
  if (!problem.empty()) return false;
  try {
    value = std::stod(text);
    return true;
  } catch (const std::exception&) {
    problem = "{" + whole + "}: '" + name + "' is not a number (" + text + ")";
    return false;
  }
}

// "ms:a+b" -> the sum of the stages' medians; "ms"; "crop.rmse" (ui_lesson_crop.h);
// "pixels:error.signed<-0.05" and the other output numbers (ui_lesson_numbers.h);
// "pct:a/b", "ratio:a/b" of two numbers or kept names; "counter".
std::string number(const UiState& state, const ScriptContext& context, const std::string& name,
                   std::string& problem) {
  if (name == "ms") return formatted(state.session.medianPipelineMs(), "%.1f");
  if (name.rfind("pct:", 0) == 0 || name.rfind("ratio:", 0) == 0) {
    const bool percent = name[0] == 'p';
    const std::string pair = name.substr(percent ? 4 : 6);
    const size_t slash = pair.find('/');
    if (slash == std::string::npos || slash == 0 || slash + 1 == pair.size()) {
      problem = "{" + name + "}: expected two numbers' names, a/b (e.g. {pct:raster4d.pairsKept/raster4d.pairsConsidered})";
      return "";
    }
    double a = 0, b = 0;
    if (!operand(state, context, name, pair.substr(0, slash), a, problem) ||
        !operand(state, context, name, pair.substr(slash + 1), b, problem))
      return "";
    if (b == 0) {
      problem = "{" + name + "}: '" + pair.substr(slash + 1) + "' is 0";
      return "";
    }
    return percent ? formatted(100 * a / b, "%.0f") : formatted(a / b, "%.3g");
  }
  if (isOutputNumber(name)) {
    double value = 0;
    if (!outputNumber(state, name, value, problem)) return "";
    const bool count = name.rfind("pixels:", 0) == 0;
    return formatted(value, count ? "%.0f" : name.rfind("share:", 0) == 0 ? "%.0f" : "%.4g");
  }
  for (const auto& [prefix, kind] : {std::pair{std::string("temporal:"), TemporalNumber::Mean},
                                     std::pair{std::string("temporal_pixel:"), TemporalNumber::WorstPixel},
                                     std::pair{std::string("temporal_spread:"), TemporalNumber::Spread}})
    if (name.rfind(prefix, 0) == 0) {  // the Temporal tab's kept pairs (window/panels/ui_temporal.h)
      double value = 0;
      std::string why;
      if (!temporalNumber(state, name.substr(prefix.size()), kind, value, why)) {
        problem = "{" + name + "}: " + why;
        return "";
      }
      return formatted(value, "%.3g");
    }
  if (name.rfind("ms:", 0) == 0) {
    double total = 0;
    std::stringstream stages(name.substr(3));
    for (std::string stage; std::getline(stages, stage, '+');) {
      double ms = 0;
      if (!stageMedian(state, stage, ms)) {
        problem = "{" + name + "}: stage '" + stage + "' did not run for the shown outputs";
        return "";
      }
      total += ms;
    }
    return formatted(total, "%.1f");
  }
  if (isCropNumber(name)) {
    double value = 0;
    if (!cropNumber(state, context.crop, name, value, problem)) return "";
    return value == std::floor(value) ? formatted(value, "%.0f") : formatted(value, "%.4g");
  }
  if (name == "triangles" && state.session.frame)  // the loaded scene's, every object's
    return formatted(double(state.session.frame->scene.triangleCount()), "%.0f");
  if (state.session.frame) {
    const auto& counters = state.session.frame->counters;
    if (const auto counter = counters.find(name); counter != counters.end())
      return counter->second == std::floor(counter->second) && std::fabs(counter->second) < 1e12
                 ? formatted(counter->second, "%.0f")  // counts as counts
                 : formatted(counter->second, "%.4g");
  }
  problem = "{" + name + "}: no such number in this run (ms, ms:stage, crop.*, pixels:, share:, min:, "
            "max:, p99:, pick:, pct:a/b, ratio:a/b, temporal:, temporal_pixel:, temporal_spread:, triangles, a kept name, or a counter such as error.rmse)";
  return "";
}

}  // namespace

std::string fillNumbers(const UiState& state, const ScriptContext& context, const std::string& text,
                        std::string& problem) {
  std::string out;
  problem.clear();
  for (size_t i = 0; i < text.size();) {
    const size_t open = text.find('{', i);
    const size_t close = open == std::string::npos ? open : text.find('}', open);
    if (close == std::string::npos) {
      out += text.substr(i);
      break;
    }
    out += text.substr(i, open - i);
    const std::string name = text.substr(open + 1, close - open - 1);
    const auto kept = context.kept.find(name);
    out += kept != context.kept.end() ? kept->second : number(state, context, name, problem);
    if (!problem.empty()) return "";
    i = close + 1;
  }
  return out;
}

std::string keepNumbers(const UiState& state, const json& a, ScriptContext& context) {
  for (const auto& [name, what] : a.items()) {
    if (!what.is_string()) return "\"" + name + "\": expected a number's name such as \"error.rmse\"";
    std::string problem;
    const std::string value = number(state, context, what.get<std::string>(), problem);
    if (!problem.empty()) return problem;
    context.kept[name] = value;
  }
  return "";
}

// 3. One exported view, recorded as a panel of the figure sheet.
std::string exportView(UiState& state, const json& a, ScriptContext& context) {
  const std::string file = a.is_string() ? a.get<std::string>() : a["file"].get<std::string>();
  const bool annotate = a.is_object() ? a.value("annotate", context.annotate) : context.annotate;
  ViewPanel& view = state.views.panels[state.views.activeView];
  std::string caption = viewCaption(state, view), problem;
  if (a.is_object() && a.contains("caption")) {
    caption = fillNumbers(state, context, a["caption"].get<std::string>(), problem);
    if (!problem.empty()) return problem;
  }
  const std::string target = context.resolved(file);
  const std::string status = exportViewFiles(state, view, target, ExportKind::Both, annotate, context.crop);
  state.status = context.shown(status);  // the final paths, not the transaction's temporary ones
  std::printf("penumbra: %s\n", state.status.c_str());
  if (status.rfind("wrote ", 0) != 0) return state.status;
  // A PNG panel keeps its raw values beside it (x.exr): the numbers behind an annotated image.
  if (fs::path(target).extension() == ".png") {
    const std::string raw = exportViewFiles(state, view, fs::path(target).replace_extension(".exr").string(),
                                            ExportKind::Both, false, context.crop);
    std::printf("penumbra: %s\n", context.shown(raw).c_str());
    if (raw.rfind("wrote ", 0) != 0) return context.shown(raw);
  }
  // "wrote /abs/x.png, /abs/x.exr": the PNG is the panel.
  std::stringstream written(status.substr(6));
  for (std::string path; std::getline(written, path, ',');) {
    path.erase(0, path.find_first_not_of(' '));
    if (path.size() > 4 && path.compare(path.size() - 4, 4, ".png") == 0)
      context.panels.push_back({path, caption});
  }
  return "";
}

std::string checkScreenshot(const json& value) {
  if (value.is_object() && value.contains("crop")) {
    const json& crop = value["crop"];
    const std::string c = crop.is_string() ? crop.get<std::string>() : "";
    const bool view = c == "view" || (c.size() == 6 && c.rfind("view:", 0) == 0 && c[5] >= '0' &&
                                      c[5] < char('0' + kMaxViews));
    if (!view && c.rfind("window:", 0) != 0)
      return "\"crop\": expected \"view\", \"view:N\" (0 to 3) or \"window:NAME\"";
    json rest = value;
    rest.erase("crop");
    rest.erase("annotate");
    return checkExportView(rest);
  }
  return checkExportView(value);
}

// The window as a panel too: saved at the end of the next frame, before the sheet is drawn.
std::string screenshot(const UiState& state, const json& a, ScriptContext& context) {
  const std::string file = a.is_string() ? a.get<std::string>() : a["file"].get<std::string>();
  context.pendingScreenshot = context.resolved(file);
  std::string caption = a.is_object() && a.contains("caption")
                            ? a["caption"].get<std::string>()
                            : "the window: " + fs::path(file).stem().string();
  std::string problem;
  caption = fillNumbers(state, context, caption, problem);
  if (!problem.empty()) return problem;
  FigurePanel panel{context.pendingScreenshot, caption};
  // Where the widget lay in the last frame (the screenshot is taken one frame later).
  const std::string crop = a.is_object() ? a.value("crop", "") : "";
  if (crop.rfind("view", 0) == 0) {
    const ViewPanel& view = state.views.panels[crop == "view" ? state.views.activeView : crop[5] - '0'];
    panel.crop = {int(view.regionOrigin.x), int(view.regionOrigin.y), int(view.regionSize.x),
                  int(view.regionSize.y)};
  } else if (!crop.empty()) {
    const ImGuiWindow* window = ImGui::FindWindowByName(crop.substr(7).c_str());
    if (!window || !window->WasActive)
      return "screenshot: no window '" + crop.substr(7) + "' is shown";
    panel.crop = {int(window->Pos.x), int(window->Pos.y), int(window->Size.x), int(window->Size.y)};
  }
  context.panels.push_back(panel);
  return "";
}

// 4. The end of a lesson: the sheet and the text beside it, then the folder's one rename
// (a lesson's files are one transaction: ScriptContext::resolved). lesson.md, the manifest
// that marks the folder as a lesson's, comes last.
std::string finishLesson(const ScriptContext& context) {
  if (context.lessonTitle.empty() || context.exportDirectory.empty()) return "";
  if (context.panels.empty() && !context.transaction) return "";
  try {
    const fs::path directory = context.transaction ? context.transaction->path() : fs::path(context.exportDirectory);
    const fs::path shown = context.transaction ? context.transaction->target() : fs::absolute(directory);
    fs::create_directories(directory);
    std::vector<fs::path> files;
    if (!context.panels.empty())
      for (const fs::path& path : writeFigureSheet(directory / "figure_sheet", context.lessonTitle,
                                                   context.panels))
        files.push_back(path.filename());
    std::string text = "# " + context.lessonTitle + "\n\n" +
                       (context.panels.empty() ? "" : "![figure sheet](figure_sheet.png)\n\n");
    for (size_t i = 0; i < context.panels.size(); ++i)
      text += "- (" + std::string(1, char('a' + i % 26)) + ") `" +
              fs::path(context.panels[i].png).filename().string() + "`: " +
              context.panels[i].caption + "\n";
    text += "\n## The lesson, as played\n\n";
    for (size_t i = 0; i < context.said.size(); ++i)
      text += std::to_string(i + 1) + ". " + context.said[i] + "\n";
    writeTextFile(directory / kLessonManifest, text);
    files.push_back(kLessonManifest);
    if (context.transaction) context.transaction->commit();
    for (const fs::path& name : files) std::printf("penumbra: wrote %s\n", (shown / name).c_str());
    std::fflush(stdout);
    return "";
  } catch (const std::exception& error) {
    return std::string("the figure sheet: ") + error.what();
  }
}
