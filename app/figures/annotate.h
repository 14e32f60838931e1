// Report-ready view PNGs (docs/lessons.md): below the image as displayed,
// a band with a colour bar (range and the channel it shows, i.e. its units), or for
// categorical masks a legend (swatch, name, share of pixels), and a caption line (scene,
// output, key parameters). Only PNGs are annotated: the EXR stays raw.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/stage.h"

struct ColorBar {
  Colormap colormap = Colormap::Gray;
  float black = 0, white = 1;  // the values at the bar's two ends
  std::string label;           // "trace.cost: fetches" (what the values count or measure)
};

struct LegendEntry {
  std::array<std::uint8_t, 3> rgb{};
  std::string text;  // "2 penumbra 12.3%"
};

struct Annotation {
  std::optional<ColorBar> bar;
  std::vector<LegendEntry> legend;
  std::string caption;
};

// The band's height in pixels for an image `width` wide (0 when there is nothing to draw).
int annotationHeight(const Annotation& annotation, int width);
// `rgb`: top-row-first RGB8, width x height. Returns the image with the band below it,
// width x (height + annotationHeight(...)).
std::vector<std::uint8_t> annotateImage(const std::vector<std::uint8_t>& rgb, int width,
                                        int height, const Annotation& annotation);
