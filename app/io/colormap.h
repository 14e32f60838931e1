// Display mappings shared by the PNG export and the window's views (docs/design.md#exports).
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "core/stage.h"

// Maps t in [0,1] to 8-bit RGB. Categorical maps take the integer value, not t.
std::array<std::uint8_t, 3> applyColormap(Colormap map, float t, float rawValue);

// Converts raw texture floats (GL order: bottom row first, `channels` per texel) into
// top-row-first RGB8 exactly as a view displays them with `hint`. NaN shows magenta,
// +Inf white, -Inf black so broken values are never silently mapped to a colour.
std::vector<std::uint8_t> displayRgb8(const std::vector<float>& values, int width, int height,
                                      int channels, const DisplayHint& hint);
