#include "window/views/ui_view_settings.h"

#include <algorithm>
#include <cmath>

#include "io/colormap.h"

// 1. Start from what the stage declared.
ViewSettings defaultViewSettings(const Output& output, int channelCount) {
  ViewSettings settings;
  const DisplayHint& hint = output.display;
  for (int c = 0; c < 4; ++c)
    settings.channels[size_t(c)] = hint.channel < 0 ? (c < std::min(channelCount, 3))
                                                    : c == hint.channel;
  settings.black = hint.black;
  settings.white = hint.white;
  settings.colormap = hint.colormap;
  settings.autoRange = hint.rangeFromData && hint.colormap != Colormap::Categorical;
  return settings;
}

// 2. One enabled channel is a single value; anything else is colour.
int singleChannel(const ViewSettings& settings, int channelCount) {
  int enabled = 0, last = -1;
  for (int c = 0; c < std::min(channelCount, 4); ++c)
    if (settings.channels[size_t(c)]) {
      ++enabled;
      last = c;
    }
  return enabled == 1 ? last : -1;
}

// 3. RGB mode is gray per channel, as app/io/colormap.cpp draws it.
DisplayHint toDisplayHint(const ViewSettings& settings, int channelCount) {
  DisplayHint hint;
  hint.channel = singleChannel(settings, channelCount);
  hint.black = settings.black;
  hint.white = settings.white;
  hint.colormap = hint.channel >= 0 ? settings.colormap : Colormap::Gray;
  return hint;
}

namespace {

// The channels whose values reach the screen: the single one, or the enabled ones of RGB.
std::vector<int> shownChannels(const ViewSettings& settings, int channelCount) {
  const int single = singleChannel(settings, channelCount);
  if (single >= 0) return {single};
  std::vector<int> shown;
  for (int c = 0; c < std::min(channelCount, 3); ++c)
    if (settings.channels[size_t(c)]) shown.push_back(c);
  return shown;
}

}  // namespace

// 4. Disabled colour channels become the black point (gray maps it to 0, as the GPU writes
//    0 for them), then app/io/colormap.cpp maps, then the overlay paints broken values.
std::vector<std::uint8_t> displayRgb8ForView(std::vector<float> values, int width, int height,
                                             int channelCount, const ViewSettings& settings) {
  const DisplayHint hint = toDisplayHint(settings, channelCount);
  const std::vector<int> shown = shownChannels(settings, channelCount);
  const std::vector<float> raw = settings.overlay ? values : std::vector<float>{};
  const size_t texels = size_t(width) * height;
  if (hint.channel < 0)
    for (int c = 0; c < std::min(channelCount, 3); ++c)
      if (!settings.channels[size_t(c)])
        for (size_t i = 0; i < texels; ++i) values[i * channelCount + c] = settings.black;
  std::vector<std::uint8_t> rgb = displayRgb8(values, width, height, channelCount, hint);
  if (!settings.overlay) return rgb;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float* texel = &raw[(size_t(height - 1 - y) * width + x) * channelCount];
      bool nan = false, inf = false, negative = false;
      for (int c : shown) {
        nan |= std::isnan(texel[c]);
        inf |= std::isinf(texel[c]);
        negative |= texel[c] < 0;
      }
      const std::array<std::uint8_t, 3>* paint = nan        ? &kOverlayNaN
                                                 : inf      ? &kOverlayInf
                                                 : negative ? &kOverlayNegative
                                                            : nullptr;
      if (paint) std::copy(paint->begin(), paint->end(), &rgb[(size_t(y) * width + x) * 3]);
    }
  return rgb;
}

// 5. Autofit ignores NaN and Inf (the overlay shows those).
bool finiteRange(const std::vector<float>& values, int channelCount,
                 const ViewSettings& settings, float& low, float& high) {
  const std::vector<int> shown = shownChannels(settings, channelCount);
  bool any = false;
  for (size_t i = 0; i + size_t(channelCount) <= values.size(); i += size_t(channelCount))
    for (int c : shown) {
      const float v = values[i + size_t(c)];
      if (!std::isfinite(v)) continue;
      low = any ? std::min(low, v) : v;
      high = any ? std::max(high, v) : v;
      any = true;
    }
  return any;
}

// 6. Names.
const char* colormapName(Colormap map) {
  switch (map) {
    case Colormap::Gray: return "gray";
    case Colormap::Perceptual: return "perceptual";
    case Colormap::Diverging: return "diverging";
    case Colormap::Categorical: return "categorical";
  }
  return "gray";
}

std::vector<std::string> colormapNames() {
  return {"gray", "perceptual", "diverging", "categorical"};
}
