// Fragment-shader passes over every texel of one target: a triangle covering the viewport,
// its corners from gl_VertexID (shaders/screen_triangle.vert), no vertex buffer.
//
// Why not a compute pass: llvmpipe writes fragment outputs a tile at a time, while a compute
// shader's imageStore goes lane by lane and, for RGBA32F, channel by channel: measured on
// the project's machine (issue 14, docs/issue14.md section 13), one RGBA32F imageStore per
// pixel of 640x480 takes 3-3.7 ms, an R32F one 0.5-0.9. Passes that write RGBA32F over
// whole images (the N-buffer's levels) are fragment-shader passes.
#pragma once
#include <glm/glm.hpp>

#include "gl/gl_texture.h"

class ScreenTriangle {
public:
  ScreenTriangle() = default;
  ~ScreenTriangle();
  ScreenTriangle(const ScreenTriangle&) = delete;
  ScreenTriangle& operator=(const ScreenTriangle&) = delete;

  // Runs the current program (screen_triangle.vert + a fragment shader writing output 0)
  // over `target`, or over layer `layer` of an array texture: depth test, blending, culling
  // and scissor off; the default framebuffer is bound again afterwards.
  void draw(const GlTexture& target, int layer = -1);
  // The same over the texels [origin, origin + size) of `target` only (the viewport).
  void drawRect(const GlTexture& target, glm::ivec2 origin, glm::ivec2 size, int layer = -1);

private:
  GlFramebuffer framebuffer_;
  GLuint vertexArray_ = 0;  // empty: core profile needs one bound to draw
};
