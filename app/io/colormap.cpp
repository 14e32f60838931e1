#include "io/colormap.h"

#include <algorithm>
#include <cmath>

namespace {
std::uint8_t toByte(float v) { return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

// Viridis, polynomial fit by Matt Zucker (public domain, 6th order), good to ~1/255.
std::array<float, 3> viridis(float t) {
  const float c0[3] = {0.2777273272234177f, 0.005407344544966578f, 0.3340998053353061f};
  const float c1[3] = {0.1050930431085774f, 1.404613529898575f, 1.384590162594685f};
  const float c2[3] = {-0.3308618287255563f, 0.214847559468213f, 0.09509516302823659f};
  const float c3[3] = {-4.634230498983486f, -5.799100973351585f, -19.33244095627987f};
  const float c4[3] = {6.228269936347081f, 14.17993336680509f, 56.69055260068105f};
  const float c5[3] = {4.776384997670288f, -13.74514537774601f, -65.35303263337234f};
  const float c6[3] = {-5.435455855934631f, 4.645852612178535f, 26.3124352495832f};
  std::array<float, 3> rgb;
  for (int i = 0; i < 3; ++i)
    rgb[i] = c0[i] + t * (c1[i] + t * (c2[i] + t * (c3[i] + t * (c4[i] + t * (c5[i] + t * c6[i])))));
  return rgb;
}
}  // namespace

std::array<std::uint8_t, 3> applyColormap(Colormap map, float t, float rawValue) {
  t = std::clamp(t, 0.0f, 1.0f);
  switch (map) {
    case Colormap::Gray: return {toByte(t), toByte(t), toByte(t)};
    case Colormap::Perceptual: {
      const auto rgb = viridis(t);
      return {toByte(rgb[0]), toByte(rgb[1]), toByte(rgb[2])};
    }
    case Colormap::Diverging: {  // blue (0) - white (0.5) - red (1)
      const float s = 2.0f * t - 1.0f;
      return s < 0 ? std::array<std::uint8_t, 3>{toByte(1 + s), toByte(1 + s), 255}
                   : std::array<std::uint8_t, 3>{255, toByte(1 - s), toByte(1 - s)};
    }
    case Colormap::Categorical: {
      static const std::uint8_t palette[8][3] = {{40, 40, 40},  {250, 220, 90}, {40, 70, 200},
                                                 {60, 200, 90}, {220, 60, 60},  {160, 90, 220},
                                                 {90, 210, 220}, {240, 150, 60}};
      const int index = int(std::lround(std::fabs(rawValue))) % 8;
      return {palette[index][0], palette[index][1], palette[index][2]};
    }
  }
  return {0, 0, 0};
}

std::vector<std::uint8_t> displayRgb8(const std::vector<float>& values, int width, int height,
                                      int channels, const DisplayHint& hint) {
  std::vector<std::uint8_t> rgb(size_t(width) * height * 3);
  const float range = hint.white - hint.black;
  const float scale = range != 0 ? 1.0f / range : 0.0f;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float* texel = &values[(size_t(height - 1 - y) * width + x) * channels];
      std::uint8_t* out = &rgb[(size_t(y) * width + x) * 3];
      const int shown = hint.channel < 0 ? std::min(channels, 3) : 1;
      for (int c = 0; c < 3; ++c) {
        const float raw = texel[hint.channel < 0 ? std::min(c, shown - 1) : hint.channel];
        std::array<std::uint8_t, 3> mapped;
        if (std::isnan(raw)) mapped = {255, 0, 255};
        else if (std::isinf(raw)) mapped = raw > 0 ? std::array<std::uint8_t, 3>{255, 255, 255}
                                                   : std::array<std::uint8_t, 3>{0, 0, 0};
        else mapped = applyColormap(hint.colormap, (raw - hint.black) * scale, raw);
        // Colour outputs map each channel through gray; single channels use the colormap.
        out[c] = hint.channel < 0 ? mapped[0] : mapped[c];
      }
    }
  return rgb;
}

bool robustRange(const std::vector<float>& values, int channels, int channel, bool symmetric,
                 float& low, float& high) {
  if (channels <= 0 || channel < 0 || channel >= channels) return false;
  std::vector<float> magnitudes;
  magnitudes.reserve(values.size() / size_t(channels));
  for (size_t i = size_t(channel); i < values.size(); i += size_t(channels))
    if (std::isfinite(values[i]) && values[i] != 0) magnitudes.push_back(std::fabs(values[i]));
  if (magnitudes.empty()) return false;
  const size_t rank = size_t(std::ceil(kRobustPercentile * double(magnitudes.size())));
  const size_t index = std::clamp<size_t>(rank, 1, magnitudes.size()) - 1;
  std::nth_element(magnitudes.begin(), magnitudes.begin() + std::ptrdiff_t(index), magnitudes.end());
  const float p = magnitudes[index];
  low = symmetric ? -p : 0.0f;
  high = p;
  return true;
}

bool applyDataRange(DisplayHint& hint, const std::vector<float>& values, int channels) {
  return hint.rangeFromData &&
         robustRange(values, channels, hint.channel, hint.colormap == Colormap::Diverging, hint.black,
                     hint.white);
}
