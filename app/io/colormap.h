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

// The range a data-ranged output (DisplayHint::rangeFromData) is shown in: p = the 99th
// percentile (nearest rank: the ceil(0.99 n)-th smallest) of |v| over the n finite, non-zero
// values of `channel` (zero is what the stages write where nothing happened: no error, no
// fetch, a pixel that does not count), then [-p, p] when `symmetric` (signed data: white
// stays at 0), else [0, p]. A few extreme pixels no longer flatten the rest. false (low and
// high untouched) when no value qualifies.
constexpr double kRobustPercentile = 0.99;
bool robustRange(const std::vector<float>& values, int channels, int channel, bool symmetric,
                 float& low, float& high);

// A data-ranged output's display (DisplayHint::rangeFromData: errors, counts) as a view first
// shows it: black and white of `hint` set to robustRange of its channel. true when the range
// came from the data; false (hint untouched) for other outputs, a channel the texture lacks,
// or no qualifying value. Used by every exported PNG (plain and annotated); the window's views
// apply robustRange to their own settings (TextureView::autoRange) the same way.
bool applyDataRange(DisplayHint& hint, const std::vector<float>& values, int channels);
