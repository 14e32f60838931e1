// Building the min-max mipmap (issue 14; layout in shaders/shared/minmax.glsl) from the
// near and far light layers: level 0 copies the layers, level n takes the min/max of the
// (up to) 2 x 2 children in level n-1, all in one atlas texture.
#pragma once
#include <glm/glm.hpp>

#include "gl/gl_texture.h"
#include "gl/shader_program.h"

// Top level: ceil(log2(max(W, H))), one texel over the whole map.
int minmaxTopLevel(int width, int height);
// Texels of level `level` per axis, and its origin in the atlas (as the GLSL functions).
glm::ivec2 minmaxLevelSize(int level, int width, int height);
glm::ivec2 minmaxLevelOrigin(int level, int width, int height);
// The atlas: (W + ceil(W/2)) x max(H, stacked heights of levels >= 1).
glm::ivec2 minmaxAtlasSize(int width, int height);

class MinMaxBuilder {
public:
  // nearLayer, farLayer: single-channel float 2D textures W x H >= 1; atlas: RGBA32F 2D,
  // minmaxAtlasSize(W, H). Throws std::invalid_argument when the shapes do not match.
  void build(const GlTexture& nearLayer, const GlTexture& farLayer, GlTexture& atlas);

private:
  ShaderProgram level_{{{GL_COMPUTE_SHADER, "minmax_level.comp"}}};
};

// The same with a process-wide builder (tests); never deleted, like buildNBuffer's.
void buildMinMax(const GlTexture& nearLayer, const GlTexture& farLayer, GlTexture& atlas);
