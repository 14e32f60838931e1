#include "window/views/ui_view_difference.h"

#include <algorithm>

#include "window/ui_graph.h"
#include "window/ui_state.h"

// 1. One program per kind of source (float / uint, 2D / array) and result format.
ShaderProgram& ViewDifference::programFor(const GlTexture& a, const GlTexture& b,
                                          GLenum resultFormat) {
  std::string defines;
  if (a.isArray()) defines += "#define A_ARRAY\n";
  if (a.isInteger()) defines += "#define A_UINT\n";
  if (b.isArray()) defines += "#define B_ARRAY\n";
  if (b.isInteger()) defines += "#define B_UINT\n";
  defines += std::string("#define RESULT_FORMAT ") +
             (resultFormat == GL_R32F ? "r32f" : resultFormat == GL_RG32F ? "rg32f" : "rgba32f") + "\n";
  return programs_[defines];
}

// 2. One dispatch, skipped when nothing changed.
const GlTexture* ViewDifference::update(const GlTexture& a, const GlTexture& b, int layer,
                                        bool clipNegative, long generation, std::string& problem) {
  if (a.width() != b.width() || a.height() != b.height()) {
    problem = "cannot subtract: " + std::to_string(a.width()) + "x" + std::to_string(a.height()) +
              " and " + std::to_string(b.width()) + "x" + std::to_string(b.height()) + " differ";
    return nullptr;
  }
  const int channels = a.channelCount();
  const GLenum format = channels == 1 ? GL_R32F : channels == 2 ? GL_RG32F : GL_RGBA32F;
  const bool same = last_.a == a.id() && last_.b == b.id() && last_.layer == layer &&
                    last_.clipNegative == clipNegative && last_.generation == generation &&
                    result_.width() == a.width() && result_.height() == a.height() &&
                    result_.internalFormat() == format;
  if (same) return &result_;
  if (result_.width() != a.width() || result_.height() != a.height() || result_.internalFormat() != format)
    result_ = GlTexture(format, a.width(), a.height());
  programFor(a, b, format).use();
  glBindTextureUnit(0, a.id());
  glBindTextureUnit(1, b.id());
  glBindImageTexture(0, result_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, format);
  glUniform2i(0, std::clamp(layer, 0, std::max(a.layers() - 1, 0)),
              std::clamp(layer, 0, std::max(b.layers() - 1, 0)));
  glUniform1i(1, clipNegative ? 1 : 0);
  glUniform1i(2, b.channelCount());
  glDispatchCompute(GLuint(a.width() + 7) / 8, GLuint(a.height() + 7) / 8, 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  last_ = {a.id(), b.id(), layer, clipNegative, generation};
  return &result_;
}

const GlTexture& ViewLevel::update(const GlTexture& source, int level, long generation) {
  level = std::clamp(level, 0, source.levels() - 1);
  if (view_.id() == 0 || last_.source != source.id() || last_.level != level ||
      last_.generation != generation) {
    view_ = GlTexture::levelView(source, level);
    last_ = {source.id(), level, generation};
  }
  return view_;
}

// 3. What a view shows.
const GlTexture* shownTexture(const UiState& state, const ViewPanel& view, std::string* problem) {
  if (!state.session.frame || !state.session.frame->has(view.output)) return nullptr;
  const GlTexture& output = state.session.frame->texture(view.output);
  const GlTexture& a = output.levels() > 1
                           ? view.level.update(output, view.settings.layer, state.session.pipelineRuns)
                           : output;
  if (view.minus.empty()) return &a;
  if (!state.session.frame->has(view.minus)) {
    if (problem) *problem = "'" + view.minus + "' was not written this frame";
    return nullptr;
  }
  std::string why;
  const GlTexture* result = view.difference.update(a, state.session.frame->texture(view.minus), view.settings.layer,
                                                   view.clipNegative, state.session.pipelineRuns, why);
  if (problem) *problem = why;
  return result;
}

std::vector<std::string> shownChannelNames(const UiState& state, const ViewPanel& view) {
  const Output* a = state.session.outputOf(view.output);
  std::vector<std::string> names = a ? a->channels : std::vector<std::string>{};
  if (view.minus.empty()) return names;
  const Output* b = state.session.outputOf(view.minus);
  for (size_t c = 0; c < names.size(); ++c)
    if (b && !b->channels.empty()) names[c] += "-" + b->channels[std::min(c, b->channels.size() - 1)];
  return names;
}

// 4. Switching on and off.
std::string setViewDifference(UiState& state, ViewPanel& view, const std::string& minus) {
  if (minus.empty()) {
    view.minus.clear();
    view.clipNegative = false;
    view.settingsFor.clear();  // back to the output's declared display
    return "";
  }
  if (!state.session.outputOf(minus)) return "unknown output '" + minus + "'";
  if (state.session.frame && state.session.frame->has(minus) && state.session.frame->has(view.output)) {
    const GlTexture& a = state.session.frame->texture(view.output);
    const GlTexture& b = state.session.frame->texture(minus);
    if (a.width() != b.width() || a.height() != b.height())
      return "'" + minus + "' is " + std::to_string(b.width()) + "x" + std::to_string(b.height()) +
             ", '" + view.output + "' " + std::to_string(a.width()) + "x" + std::to_string(a.height());
  }
  if (view.settingsFor != view.output) {  // settings of this output first (not yet drawn)
    if (const Output* output = state.session.outputOf(view.output))
      view.settings = defaultViewSettings(*output, int(output->channels.size()));
    view.settingsFor = view.output;
  }
  view.minus = minus;
  // One channel through the diverging map: red where A > B, blue where A < B.
  const int first = std::find(view.settings.channels.begin(), view.settings.channels.end(), true) -
                    view.settings.channels.begin();
  for (int c = 0; c < 4; ++c) view.settings.channels[size_t(c)] = c == std::min(first, 3);
  view.settings.colormap = Colormap::Diverging;
  view.autofitPending = true;
  return "";
}

std::string showThickness(UiState& state) {
  ViewPanel* target = state.views.selectionTarget();
  if (!target) return "both views are locked: unlock one to show the thickness";
  const LayerOutputs layers = layerOutputs(state.session.pipeline);
  if (layers.far.empty()) return "no stage declares the outputs near and far (the light layers)";
  if (std::string problem = state.selectOutput(layers.far); !problem.empty()) return problem;
  std::string problem = setViewDifference(state, *target, layers.near);
  if (problem.empty()) target->clipNegative = true;
  return problem;
}
