// Building the min-max mipmap (layout in shaders/shared/minmax.glsl;
// docs/decisions/024-minmax-mipmap-levels.md) from the near and far light layers: level 0 is the
// layers themselves (not stored), level n >= 1 takes the min/max of the (up to) 2 x 2 children in
// level n-1 and is mip level n - 1 of one texture.
#pragma once
#include <glm/glm.hpp>

#include "gl/gl_texture.h"
#include "gl/screen_triangle.h"
#include "gl/shader_program.h"

// Top level: ceil(log2(max(W, H))), one texel over the whole map.
int minmaxTopLevel(int width, int height);
// Texels of level `level` per axis (the cells; gl/hierarchy_cells.h).
glm::ivec2 minmaxLevelSize(int level, int width, int height);
// The texture of the levels >= 1: RGBA32F 2D, base minmaxBaseSize per axis (the next power of
// two of ceil(W/2) x ceil(H/2)), minmaxMipLevels mip levels; 1 x 1 with one level for a 1 x 1
// map. The hierarchy's level n is mip level n - 1.
glm::ivec2 minmaxBaseSize(int width, int height);
int minmaxMipLevels(int width, int height);

class MinMaxBuilder {
public:
  // nearLayer, farLayer: single-channel float 2D textures W x H >= 1; levels: RGBA32F 2D of
  // minmaxBaseSize(W, H) with minmaxMipLevels(W, H) levels. Throws std::invalid_argument when
  // the shapes do not match.
  void build(const GlTexture& nearLayer, const GlTexture& farLayer, GlTexture& levels);

private:
  // Level 1 from the layers, the coarser levels from the level below (minmax_level.frag says
  // why two programs).
  ShaderVariants levelPrograms_{{{GL_VERTEX_SHADER, "shared/screen_triangle.vert"},
                                 {GL_FRAGMENT_SHADER, "shared_inputs/minmax/minmax_level.frag"}},
                                {"#define MINMAX_FROM_LAYERS 0\n", "#define MINMAX_FROM_LAYERS 1\n"}};
  ScreenTriangle screen_;
};

// The same with a process-wide builder (tests); never deleted, like buildNBuffer's.
void buildMinMax(const GlTexture& nearLayer, const GlTexture& farLayer, GlTexture& levels);
// A texture of the shape build() takes, built (tests, the ray-query runner).
GlTexture buildMinMaxLevels(const GlTexture& nearLayer, const GlTexture& farLayer);
