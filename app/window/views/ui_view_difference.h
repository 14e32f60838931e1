// A view of the difference of two stage outputs, A - B (docs/design.md#window): the light layers'
// thickness (far - near), or any comparison of two outputs. Generic: any two
// outputs of the same size, e.g.
//   light_layers.far - light_layers.near   occluder thickness where both layers are covered
//                                          (uncovered texels give 0 - 1 < 0: "negative -> 0")
//   filter.visibility - trace.visibility   what the filter changed
//   trace.visibility - reference.visibility  the method's error (as the `error` stage)
// The difference is computed on the GPU (shaders/view/view_difference.comp) into a float texture
// that the view then shows, reads back, autofits and exports like any output. It starts
// with the diverging colormap, symmetric about 0.
#pragma once
#include <string>

#include "gl/gl_texture.h"
#include "gl/shader_program.h"

class UiState;
struct ViewPanel;

class ViewDifference {
public:
  // A - B: B's channel c (or its last one) under A's channel c; layer `layer` of arrays.
  // The result has A's channel count, float. Recomputed only when an input, the layer,
  // `clipNegative` or `generation` (the pipeline's run count) changed. Returns nullptr and
  // sets `problem` where the two cannot be subtracted (sizes differ).
  const GlTexture* update(const GlTexture& a, const GlTexture& b, int layer, bool clipNegative,
                          long generation, std::string& problem);

private:
  ShaderProgram& programFor(const GlTexture& a, const GlTexture& b, GLenum resultFormat);
  ShaderVariants programs_{{{GL_COMPUTE_SHADER, "view/view_difference.comp"}}};
  GlTexture result_;
  struct Key {
    GLuint a = 0, b = 0;
    int layer = -1;
    bool clipNegative = false;
    long generation = -1;
  } last_;
};

// One mip level of a mipmapped output (the min-max mipmap) as a texture of its own, a view
// of that level's storage (GlTexture::levelView): what the view renders, reads back, fits
// and exports is the level, at its size. Made again when the source, the level or
// `generation` (the pipeline's run count) changed.
class ViewLevel {
public:
  const GlTexture& update(const GlTexture& source, int level, long generation);

private:
  GlTexture view_;
  struct Key {
    GLuint source = 0;
    int level = -1;
    long generation = -1;
  } last_;
};

// The texture a view shows: its output (of a mipmapped output, mip level settings.layer),
// or output - minus. Null when not written (or when
// the difference is impossible: `problem` says why, if given).
const GlTexture* shownTexture(const UiState& state, const ViewPanel& view,
                              std::string* problem = nullptr);

// Turns the difference view on (`minus` = "stage.output") or off (""): checks the output
// exists and has the view's size, switches to the diverging colormap, autofits. "" or why not.
std::string setViewDifference(UiState& state, ViewPanel& view, const std::string& minus);
// The thickness preset: the light layers' far - near (ui_graph.h layerOutputs), negative
// (uncovered) -> 0.
// In the view that takes selections (app/window/ui_state.h selectionTarget).
std::string showThickness(UiState& state);
// Channel names of the shown texture ("lsDepthFar-lsDepthNear"), for readouts and EXR.
std::vector<std::string> shownChannelNames(const UiState& state, const ViewPanel& view);
