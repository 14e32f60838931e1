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

// Small outputs (hash_stats' 64 x 64 histogram, its 16 x 160 bit bars) would clip the band's
// labels: they are enlarged first by a whole factor, nearest neighbour (each texel a
// factor x factor block, nothing interpolated), the smallest that makes them
// kAnnotatedMinWidth wide without passing kAnnotatedMaxHeight; an image still narrower than
// that is centred on a white canvas of
// that width, a grey edge either side. Images already wide enough are unchanged.
constexpr int kAnnotatedMinWidth = 400, kAnnotatedMaxHeight = 800;
int annotationEnlargement(int width, int height);
struct AnnotatedImage {
  std::vector<std::uint8_t> rgb;  // top-row-first RGB8
  int width = 0, height = 0;
};
// Enlarges (annotationEnlargement), pads to kAnnotatedMinWidth when needed, then annotates.
AnnotatedImage annotateView(const std::vector<std::uint8_t>& rgb, int width, int height,
                            const Annotation& annotation);
