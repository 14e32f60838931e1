// Fragment-shader passes over every texel of their targets: a triangle covering the
// viewport, its corners from gl_VertexID (shaders/shared/screen_triangle.vert), no vertex buffer.
//
// Why not a compute pass: llvmpipe writes fragment outputs a tile at a time, while a compute
// shader's imageStore goes lane by lane and, for RGBA32F, channel by channel: measured on
// the project's machine (docs/decisions/013-whole-image-passes-as-fragment-passes.md), one RGBA32F
// imageStore per pixel of 640x480 takes 5.1 ms, an R32F one 0.9. Passes that write whole images
// (the N-buffer's and min-max mipmap's levels, classification, the composite) are fragment-shader
// passes.
#pragma once
#include <glm/glm.hpp>

#include <vector>

#include "gl/gl_texture.h"

class ScreenTriangle {
public:
  ScreenTriangle() = default;
  ~ScreenTriangle();
  ScreenTriangle(const ScreenTriangle&) = delete;
  ScreenTriangle& operator=(const ScreenTriangle&) = delete;

  // Runs the current program (screen_triangle.vert + a fragment shader writing output i to
  // targets[i]) over the targets, all of one size, or over layer `layer` of an array
  // texture: depth test, blending, culling and scissor off; the default framebuffer is bound
  // again afterwards.
  void draw(const std::vector<const GlTexture*>& targets, int layer = -1);
  void draw(const GlTexture& target, int layer = -1) { draw({&target}, layer); }
  // The same into layers[i] of one array texture as output i (several levels in one pass).
  void drawLayers(const GlTexture& array, const std::vector<int>& layers);
  // The same after clearing target i to clearTo[i] (one value per target), as a clear of
  // the framebuffer the triangle is drawn into: llvmpipe then clears each tile as it shades
  // it, where glClearTexImage is a separate pass over memory on the calling thread
  // (classification's two targets: 0.9-1.1 ms more per 640x480 frame, measured on llvmpipe).
  void clearAndDraw(const std::vector<const GlTexture*>& targets,
                    const std::vector<glm::vec4>& clearTo);
  // The same over the texels [origin, origin + size) of one target only (the viewport).
  void drawRect(const GlTexture& target, glm::ivec2 origin, glm::ivec2 size) {
    drawRect({{&target, -1}}, origin, size);
  }
  void drawRect(const GlTexture& target, int layer, glm::ivec2 origin, glm::ivec2 size) {
    drawRect({{&target, layer}}, origin, size);
  }

  // The same with `depth` as the depth attachment, written with each fragment's depth
  // whatever is there (GL_ALWAYS): a pass that rewrites a depth layer (the risers pass).
  void drawRectWithDepth(const GlTexture& target, const GlTexture& depth, glm::ivec2 origin,
                         glm::ivec2 size) {
    drawRect({{&target, -1}}, origin, size, {}, &depth);
  }

private:
  struct Target {
    const GlTexture* texture;
    int layer;  // -1: the whole texture (not layered)
  };
  void drawRect(const std::vector<Target>& targets, glm::ivec2 origin, glm::ivec2 size,
                const std::vector<glm::vec4>& clearTo = {}, const GlTexture* depth = nullptr);
  GlFramebuffer framebuffer_;
  GLuint vertexArray_ = 0;  // empty: core profile needs one bound to draw
};
