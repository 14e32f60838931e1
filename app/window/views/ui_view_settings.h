// How one view maps a stage output to colours (RenderDoc's texture viewer controls): channel
// toggles, black/white point, colormap, NaN/Inf/negative overlay, array layer. The GPU
// mapping (shaders/view/view.comp via app/window/views/texture_view.h) and this CPU twin (used by "PNG as
// displayed") must agree byte for byte; tests/window/test_window_view.cpp checks it.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/stage.h"

struct ViewSettings {
  std::array<bool, 4> channels{true, true, true, false};  // R G B A toggles
  float black = 0, white = 1;
  Colormap colormap = Colormap::Gray;
  bool overlay = false;  // paint NaN, Inf and negative values of the shown channels
  int layer = 0;         // array textures (the N-buffer: one layer per level)
  // black/white follow the data (robustRange, app/io/colormap.h), recomputed once per run,
  // until the user sets a range (drag, type, Autofit, a script's or settings file's range).
  bool autoRange = false;
};

// Overlay colours (display only; never confused with a colormap because they are saturated
// primaries no map here produces at full strength).
constexpr std::array<std::uint8_t, 3> kOverlayNaN{255, 0, 255};
constexpr std::array<std::uint8_t, 3> kOverlayInf{0, 255, 0};
constexpr std::array<std::uint8_t, 3> kOverlayNegative{0, 0, 255};

// 1. The settings a fresh view starts from: the output's declared DisplayHint (auto range
//    for outputs declared rangeFromData).
ViewSettings defaultViewSettings(const Output& output, int channelCount);

// 2. Exactly one enabled channel (of the texture's `channelCount`) -> its index, shown as a
//    single value through the colormap; otherwise -1: RGB, each enabled channel in gray.
int singleChannel(const ViewSettings& settings, int channelCount);

// 3. The DisplayHint equivalent (RGB mode always maps through gray, as app/io/colormap.cpp).
DisplayHint toDisplayHint(const ViewSettings& settings, int channelCount);

// 4. CPU twin of the GPU view: raw floats (GL order) -> top-row-first RGB8 as displayed.
std::vector<std::uint8_t> displayRgb8ForView(std::vector<float> values, int width, int height,
                                             int channelCount, const ViewSettings& settings);

// 5. Min and max over finite values of the shown channels (for autofit); false if none.
bool finiteRange(const std::vector<float>& values, int channelCount,
                 const ViewSettings& settings, float& low, float& high);

// 6. Names for the UI and the settings file.
const char* colormapName(Colormap map);
std::vector<std::string> colormapNames();
