// Building the N-buffer (thesis §3.5; layout in shaders/shared/nbuffer.glsl) from the near
// and far light layers: level 0 copies the layers, level n takes the min/max of 4 texels of
// level n-1. Reusable outside the `nbuffer` stage (tests, other stages).
#pragma once
#include "gl/gl_texture.h"
#include "gl/screen_triangle.h"
#include "gl/shader_program.h"

// Levels 0 .. ceil(log2(max(width, height))): the coarsest level's window is the whole map.
int nbufferLevelCount(int width, int height);

// Owns the two programs (fragment-shader passes, one per level); a stage keeps one so its
// programs die with it (before the GL context does).
class NBufferBuilder {
public:
  // nearLayer, farLayer: GL_DEPTH_COMPONENT32F (or any single-channel float) textures of the
  // same size W x H >= 1. levels: GL_RGBA32F 2D array, W x H, nbufferLevelCount(W, H) layers.
  // Throws std::invalid_argument when the shapes do not match.
  void build(const GlTexture& nearLayer, const GlTexture& farLayer, GlTexture& levels);

private:
  ShaderProgram level0_{{{GL_VERTEX_SHADER, "screen_triangle.vert"},
                         {GL_FRAGMENT_SHADER, "nbuffer_level0.frag"}}};
  ShaderProgram level_{{{GL_VERTEX_SHADER, "screen_triangle.vert"},
                        {GL_FRAGMENT_SHADER, "nbuffer_level.frag"}}};
  ScreenTriangle screen_;
};

// The same with a process-wide builder (for tests and one-off use). Its programs are
// deliberately never deleted, so no GL call runs after the context is gone at exit.
void buildNBuffer(const GlTexture& nearLayer, const GlTexture& farLayer, GlTexture& levels);
