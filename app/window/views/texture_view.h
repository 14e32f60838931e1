// Renders a stage output into an RGBA8 texture for display (the window's views), with the
// same mapping as the "PNG as displayed" export (app/window/views/ui_view_settings.h), and reads raw
// texels back for the hover readout, the inspector and autofit.
#pragma once
#include <array>
#include <vector>

#include "gl/gl_texture.h"
#include "gl/shader_program.h"
#include "core/stage.h"
#include "window/views/ui_view_settings.h"

class TextureView {
public:
  // Maps layer `settings.layer` of `source`; returns the display texture (same size).
  const GlTexture& render(const GlTexture& source, const ViewSettings& settings);
  // The same, skipped when source, settings and `generation` (bumped whenever the source's
  // contents change: the pipeline's run count) are those of the last call.
  const GlTexture& render(const GlTexture& source, const ViewSettings& settings, long generation);
  // The declared default mapping (layer 0), as `penumbra export` writes the PNG.
  const GlTexture& render(const GlTexture& source, const DisplayHint& hint);
  // An auto-ranged view (settings.autoRange): black/white = robustRange of the shown channel
  // of layer settings.layer. The texture is read back only when source, generation, layer or
  // channel differ from the last call (once per pipeline run, not per UI frame); otherwise
  // the range found then is applied again. Nothing changes for a colour (RGB) view or when
  // no value is written (the declared range stays).
  void autoRange(const GlTexture& source, ViewSettings& settings, long generation);

private:
  ShaderProgram& programFor(const GlTexture& source);
  ShaderProgram float2D_{{{GL_COMPUTE_SHADER, "view/view.comp"}}};
  ShaderProgram floatArray_{{{GL_COMPUTE_SHADER, "view/view.comp"}}, "#define SOURCE_ARRAY\n"};
  ShaderProgram uint2D_{{{GL_COMPUTE_SHADER, "view/view.comp"}}, "#define SOURCE_UINT\n"};
  ShaderProgram uintArray_{{{GL_COMPUTE_SHADER, "view/view.comp"}},
                           "#define SOURCE_UINT\n#define SOURCE_ARRAY\n"};
  GlTexture display_;
  struct Key {
    GLuint source = 0;
    long generation = -1;
    ViewSettings settings;
  } last_;
  struct RangeKey {
    GLuint source = 0;
    long generation = -1;
    int layer = -1, channel = -1;
    bool found = false;
    float low = 0, high = 1;
  } range_;
};

// Raw values of one texel (x, y in GL order: row 0 at the bottom) of layer `layer`; the
// texture's channelCount() entries are meaningful, the rest 0. Integer formats converted.
std::array<float, 4> readTexel(const GlTexture& texture, int x, int y, int layer = 0);

// Raw values of a rectangle (GL order, channelCount() per texel), clamped to the texture.
std::vector<float> readRegion(const GlTexture& texture, int x0, int y0, int width, int height,
                              int layer = 0);
