// Building the min-max mipmap (layout in shaders/shared/minmax.glsl;
// docs/decisions/024-minmax-mipmap-atlas.md) from the near and far light layers: level 0 is the
// layers themselves (not stored), level n >= 1 takes the min/max of the (up to) 2 x 2 children in
// level n-1, levels >= 1 in one atlas.
#pragma once
#include <glm/glm.hpp>

#include "gl/gl_texture.h"
#include "gl/screen_triangle.h"
#include "gl/shader_program.h"

// Top level: ceil(log2(max(W, H))), one texel over the whole map.
int minmaxTopLevel(int width, int height);
// Texels of level `level` per axis, and the origin in the atlas of a level >= 1: the
// shaders' functions (gl/hierarchy_cells.h).
glm::ivec2 minmaxLevelSize(int level, int width, int height);
glm::ivec2 minmaxLevelOrigin(int level, int width, int height);
// The atlas: ceil(W/2) x (stacked heights of levels >= 1); 1 x 1 for a 1 x 1 map.
glm::ivec2 minmaxAtlasSize(int width, int height);

class MinMaxBuilder {
public:
  // nearLayer, farLayer: single-channel float 2D textures W x H >= 1; atlas: RGBA32F 2D,
  // minmaxAtlasSize(W, H). Throws std::invalid_argument when the shapes do not match.
  void build(const GlTexture& nearLayer, const GlTexture& farLayer, GlTexture& atlas);

private:
  // Level 1 from the layers, the coarser levels from the atlas (minmax_level.frag says why
  // two programs).
  ShaderVariants levelPrograms_{{{GL_VERTEX_SHADER, "screen_triangle.vert"},
                                 {GL_FRAGMENT_SHADER, "minmax_level.frag"}},
                                {"#define MINMAX_FROM_LAYERS 0\n", "#define MINMAX_FROM_LAYERS 1\n"}};
  ScreenTriangle screen_;
};

// The same with a process-wide builder (tests); never deleted, like buildNBuffer's.
void buildMinMax(const GlTexture& nearLayer, const GlTexture& farLayer, GlTexture& atlas);
