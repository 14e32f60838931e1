// The N-buffer's windows and the min-max mipmap's cells in C++: the same text as the shaders
// compile (shaders/shared/hierarchy_cells.h), with glm standing in for GLSL's built-ins.
#pragma once
#include <glm/glm.hpp>
#include <glm/integer.hpp>

namespace cells {
using glm::clamp;
using glm::findMSB;
using glm::ivec2;
using glm::max;
using glm::min;
#include "shared/hierarchy_cells.h"
}  // namespace cells
