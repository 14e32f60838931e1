// N-buffer views (docs/design.md#window): the level-0 window that the hovered texel
// of level n summarises, drawn as a rectangle. The N-buffer is the output wired to the
// trace's "levels" slot (window/ui_graph.h recordingInput), one array layer per level. The
// window rule is the shaders' own (shaders/shared/hierarchy_cells.h nbufferWindow1D, through
// gl/hierarchy_cells.h), for levels the user may type past the map's.
#pragma once
#include <glm/glm.hpp>
#include <string>

// Per axis: the inclusive window [lo, hi] of level `level` texel `x` on a map of `size`.
glm::ivec2 nbufferWindow1D(int level, int x, int size);
// The inclusive level-0 window of texel `texel` of level `level`.
void nbufferWindow(int level, glm::ivec2 texel, glm::ivec2 size, glm::ivec2& lo, glm::ivec2& hi);
