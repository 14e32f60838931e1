// Renders a stage output into an RGBA8 texture for display (the window's views), with the
// same mapping as the PNG export (app/colormap.h).
#pragma once
#include "gl_texture.h"
#include "shader_program.h"
#include "stage.h"

class TextureView {
public:
  // Maps layer 0 of `source` with `hint`; returns the display texture (same size).
  const GlTexture& render(const GlTexture& source, const DisplayHint& hint);

private:
  ShaderProgram program_{{{GL_COMPUTE_SHADER, "view.comp"}}};
  GlTexture display_;
};
