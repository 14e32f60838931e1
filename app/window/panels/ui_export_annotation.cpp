#include "window/panels/ui_export_annotation.h"

#include "window/ui_state.h"
#include "window/views/ui_categories.h"
#include "window/views/ui_view_difference.h"

// 1. Scene, what the view shows, its size, and the parameters that differ from their
//    declared defaults: the shown stage's first (as the export file name lists them,
//    app/window/panels/ui_export.h), then those of every stage it depends on, so that two
//    panels of a lesson at different map sizes or passes say how they differ.
std::string viewCaption(const UiState& state, const ViewPanel& view) {
  std::string shown = view.output;
  if (!view.minus.empty()) shown += " minus " + view.minus + (view.clipNegative ? " (>= 0)" : "");
  if (state.session.frame && state.session.frame->has(view.output) &&
      state.session.frame->texture(view.output).isArray())
    shown += " level " + std::to_string(view.settings.layer);
  std::string caption = state.session.scene.name + " · " + shown;
  if (const GlTexture* texture = shownTexture(state, view))  // its own size: maps are not eye-sized
    caption += " · " + std::to_string(texture->width()) + "x" + std::to_string(texture->height());
  const std::string stageName = view.output.substr(0, view.output.find('.'));
  const Pipeline& pipeline = state.session.pipeline;
  if (!pipeline.hasStage(stageName)) return caption;
  std::vector<std::string> stageNames = {stageName};
  for (const std::string& name : pipeline.dependencies({view.output}))
    if (name != stageName) stageNames.push_back(name);
  std::string changed;
  for (const std::string& name : stageNames) {
    for (const Param& param : pipeline.stage(name).params()) {
      const auto declared = state.session.parameterDefaults.find(name + "." + param.key);
      if (declared != state.session.parameterDefaults.end() && declared->second == param.value)
        continue;
      // The pixel whose steps are recorded or whose mask is shown: a pick, not a setting.
      if (param.key.rfind("record_", 0) == 0 || param.key.rfind("pick_", 0) == 0) continue;
      // The shown stage's own keys stay short; the others name their stage.
      const std::string key = name == stageName ? param.key : name + "." + param.key;
      changed += (changed.empty() ? "" : ", ") + key + "=" + param.toString();
    }
  }
  return changed.empty() ? caption : caption + " · " + changed;
}

// 2. A single channel: its colour bar, or its legend when the map is categorical.
Annotation viewAnnotation(const UiState& state, const ViewPanel& view,
                          const std::vector<float>& values, int channelCount) {
  Annotation annotation;
  annotation.caption = viewCaption(state, view);
  const int channel = singleChannel(view.settings, channelCount);
  if (channel < 0) return annotation;  // colour: the image is its own key
  const std::vector<std::string> names = shownChannelNames(state, view);
  const std::string channelName =
      channel < int(names.size()) ? names[size_t(channel)] : std::string(1, "RGBA"[channel]);
  if (view.settings.colormap != Colormap::Categorical) {
    annotation.bar = ColorBar{view.settings.colormap, view.settings.black, view.settings.white,
                              view.output + (view.minus.empty() ? "" : " - " + view.minus) +
                                  ": " + channelName +
                                  (view.settings.autoRange ? " · auto range (p99)" : "")};
    return annotation;
  }
  const Output* output = state.session.outputOf(view.output);
  annotation.legend = categoryLegend(values, channelCount, channel, output ? output->doc : "");
  return annotation;
}
