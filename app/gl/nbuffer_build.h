// Building the N-buffer (thesis §3.5; layout in shaders/shared/nbuffer.glsl) from the near
// and far light layers: level 0 copies the layers and level 1 takes the min/max of their
// 2x2 texels (one pass), level n >= 2 the min/max of 4 texels of level n-1. Reusable
// outside the `nbuffer` stage (tests, other stages).
#pragma once
#include "gl/gl_texture.h"
#include "gl/screen_triangle.h"
#include "gl/shader_program.h"

// Levels 0 .. ceil(log2(max(width, height))): the coarsest level's window is the whole map.
int nbufferLevelCount(int width, int height);

// Per axis of `size` texels, the texels of level `level` whose windows differ: `count` of
// them from `first`, the ones nbufferTexelForWindow (shaders/shared/nbuffer.glsl) returns.
// The rest, bands of 2^(level-1) texels at the borders, repeat the border windows.
struct TexelSpan {
  int first = 0, count = 0;
};
TexelSpan nbufferDistinctTexels(int level, int size);

// Which texels of levels >= 2 a build writes: all, or only those holding distinct windows
// (every read of the hierarchy goes to those; the stage writes all only when the levels are
// shown or exported: docs/decisions/014-outputs-nobody-asked-for.md, 29 % fewer texels over levels
// 1-9 at 512^2). Levels 0 and 1 come from one pass over every texel either way.
enum class NBufferTexels { All, Distinct };

// Owns the two programs (fragment-shader passes: levels 0 and 1 together, then one per
// level); a stage keeps one so its programs die with it (before the GL context does).
class NBufferBuilder {
public:
  // nearLayer, farLayer: GL_DEPTH_COMPONENT32F (or any single-channel float) textures of the
  // same size W x H >= 1. levels: GL_RGBA32F 2D array, W x H, nbufferLevelCount(W, H) layers.
  // Throws std::invalid_argument when the shapes do not match.
  void build(const GlTexture& nearLayer, const GlTexture& farLayer, GlTexture& levels,
             NBufferTexels texels = NBufferTexels::All);

private:
  ShaderProgram levels01_{{{GL_VERTEX_SHADER, "shared/screen_triangle.vert"},
                           {GL_FRAGMENT_SHADER, "shared_inputs/nbuffer/nbuffer_levels01.frag"}}};
  ShaderProgram level_{{{GL_VERTEX_SHADER, "shared/screen_triangle.vert"},
                        {GL_FRAGMENT_SHADER, "shared_inputs/nbuffer/nbuffer_level.frag"}}};
  ScreenTriangle screen_;
};

// The same with a process-wide builder (for tests and one-off use). Its programs are
// deliberately never deleted, so no GL call runs after the context is gone at exit.
void buildNBuffer(const GlTexture& nearLayer, const GlTexture& farLayer, GlTexture& levels);
