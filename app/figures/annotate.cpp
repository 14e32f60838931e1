#include "figures/annotate.h"

#include <cairo.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "figures/cairo_text.h"
#include "io/colormap.h"

namespace {

constexpr int kPad = 6, kLine = 16, kBarHeight = 12, kSwatch = 10;
constexpr double kFontSize = 11;

std::string number(float value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", double(value));
  return text;
}

// Legend entries flow left to right; the number of rows they need at `width`.
int legendRows(const Annotation& annotation, int width, cairo_t* cr) {
  if (annotation.legend.empty()) return 0;
  int rows = 1;
  double x = kPad;
  for (const LegendEntry& entry : annotation.legend) {
    const double w = kSwatch + 4 + textWidth(cr, entry.text, kFontSize) + 14;
    if (x + w > width - kPad && x > kPad) {
      ++rows;
      x = kPad;
    }
    x += w;
  }
  return rows;
}

// The bar's middle tick with its label ("0.5   error.signed"), centred on the middle value.
std::string middleTick(const ColorBar& bar, bool withLabel) {
  const std::string middle = number(0.5f * (bar.black + bar.white));
  return withLabel ? middle + "   " + bar.label : middle;
}

// On a narrow image the label after the middle tick would run into the high end's value:
// it then gets a line of its own under the ticks.
bool barLabelOnOwnLine(const ColorBar& bar, int width, cairo_t* cr) {
  const double middleLeft = 0.5 * width - 0.5 * textWidth(cr, middleTick(bar, false), kFontSize);
  const double highLeft = width - kPad - textWidth(cr, number(bar.white), kFontSize);
  return middleLeft + textWidth(cr, middleTick(bar, true), kFontSize) + 4 > highLeft;
}

// Caption lines: two, or four on images too narrow for the scene, output and parameters.
int captionLines(int width) { return width < 400 ? 4 : 2; }

int bandHeight(const Annotation& annotation, int width, cairo_t* cr) {
  int height = 0;
  if (annotation.bar) {
    height += kBarHeight + 2 + kLine + 2;  // bar, then its tick labels
    if (barLabelOnOwnLine(*annotation.bar, width, cr)) height += kLine;
  }
  height += legendRows(annotation, width, cr) * kLine;
  if (!annotation.caption.empty()) height += kLine * captionLines(width);
  return height == 0 ? 0 : height + 2 * kPad;
}

cairo_t* measuringContext(cairo_surface_t*& surface) {
  surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 1, 1);
  return cairo_create(surface);
}

}  // namespace

int annotationHeight(const Annotation& annotation, int width) {
  cairo_surface_t* surface = nullptr;
  cairo_t* cr = measuringContext(surface);
  const int height = bandHeight(annotation, width, cr);
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
  return height;
}

std::vector<std::uint8_t> annotateImage(const std::vector<std::uint8_t>& rgb, int width,
                                        int height, const Annotation& annotation) {
  const int band = annotationHeight(annotation, width);
  if (band == 0) return rgb;
  const int total = height + band;
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, total);
  cairo_t* cr = cairo_create(surface);
  // 1. White band; the image copied above it.
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_surface_flush(surface);
  unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::uint8_t* p = &rgb[(size_t(y) * width + x) * 3];
      auto* pixel = reinterpret_cast<std::uint32_t*>(data + size_t(y) * stride) + x;
      *pixel = 0xFF000000u | (std::uint32_t(p[0]) << 16) | (std::uint32_t(p[1]) << 8) | p[2];
    }
  cairo_surface_mark_dirty(surface);
  double y = height + kPad;
  // 2. The colour bar: the colormap from black to white, the end values and the middle.
  if (annotation.bar) {
    const ColorBar& bar = *annotation.bar;
    const double x0 = kPad, x1 = width - kPad;
    for (int x = int(x0); x < int(x1); ++x) {
      const float t = float((x - x0) / std::max(1.0, x1 - x0 - 1));
      const auto c = applyColormap(bar.colormap, t, bar.black + t * (bar.white - bar.black));
      cairo_set_source_rgb(cr, c[0] / 255.0, c[1] / 255.0, c[2] / 255.0);
      cairo_rectangle(cr, x, y, 1, kBarHeight);
      cairo_fill(cr);
    }
    cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
    cairo_set_line_width(cr, 1);
    cairo_rectangle(cr, x0 + 0.5, y + 0.5, x1 - x0 - 1, kBarHeight - 1);
    cairo_stroke(cr);
    y += kBarHeight + 2;
    const std::string low = number(bar.black), high = number(bar.white);
    const bool ownLine = barLabelOnOwnLine(bar, width, cr);
    drawText(cr, x0, y, low, kFontSize, 0.1);
    drawText(cr, x1 - textWidth(cr, high, kFontSize), y, high, kFontSize, 0.1);
    drawText(cr, 0.5 * width - 0.5 * textWidth(cr, middleTick(bar, false), kFontSize), y,
             middleTick(bar, !ownLine), kFontSize, 0.1);
    y += kLine + 2;
    if (ownLine) {
      drawText(cr, 0.5 * width - 0.5 * textWidth(cr, bar.label, kFontSize), y, bar.label, kFontSize, 0.1);
      y += kLine;
    }
  }
  // 3. The legend: swatch and text per category, wrapped into rows.
  if (!annotation.legend.empty()) {
    double x = kPad;
    for (const LegendEntry& entry : annotation.legend) {
      const double w = kSwatch + 4 + textWidth(cr, entry.text, kFontSize) + 14;
      if (x + w > width - kPad && x > kPad) {
        x = kPad;
        y += kLine;
      }
      cairo_set_source_rgb(cr, entry.rgb[0] / 255.0, entry.rgb[1] / 255.0, entry.rgb[2] / 255.0);
      cairo_rectangle(cr, x, y + 3, kSwatch, kSwatch);
      cairo_fill_preserve(cr);
      cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
      cairo_stroke(cr);
      drawText(cr, x + kSwatch + 4, y, entry.text, kFontSize, 0.1);
      x += w;
    }
    y += kLine;
  }
  // 4. The caption: scene, output, key parameters (two lines at most, four when narrow).
  for (const std::string& line :
       wrapText(cr, annotation.caption, kFontSize, width - 2 * kPad, captionLines(width))) {
    drawText(cr, kPad, y, line, kFontSize, 0.25);
    y += kLine;
  }
  // 5. Back to RGB8.
  cairo_surface_flush(surface);
  const cairo_status_t status = cairo_status(cr);
  std::vector<std::uint8_t> out(size_t(width) * total * 3);
  for (int row = 0; row < total; ++row)
    for (int x = 0; x < width; ++x) {
      const std::uint32_t pixel = reinterpret_cast<const std::uint32_t*>(data + size_t(row) * stride)[x];
      std::uint8_t* q = &out[(size_t(row) * width + x) * 3];
      q[0] = std::uint8_t(pixel >> 16), q[1] = std::uint8_t(pixel >> 8), q[2] = std::uint8_t(pixel);
    }
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(std::string("annotating a PNG: ") + cairo_status_to_string(status));
  return out;
}

int annotationEnlargement(int width, int height) {
  if (width <= 0 || height <= 0 || width >= kAnnotatedMinWidth) return 1;
  const int wide = (kAnnotatedMinWidth + width - 1) / width;  // reaches the width
  const int tall = std::max(1, kAnnotatedMaxHeight / height);    // stays below the height cap
  return std::max(1, std::min(wide, tall));
}

AnnotatedImage annotateView(const std::vector<std::uint8_t>& rgb, int width, int height,
                            const Annotation& annotation) {
  const int factor = annotationEnlargement(width, height);
  const int scaledWidth = width * factor, scaledHeight = height * factor;
  const int canvasWidth = std::max(scaledWidth, kAnnotatedMinWidth);
  const int left = (canvasWidth - scaledWidth) / 2;
  std::vector<std::uint8_t> canvas(size_t(canvasWidth) * scaledHeight * 3, 255);
  for (int y = 0; y < scaledHeight; ++y)
    for (int x = 0; x < scaledWidth; ++x)
      std::copy_n(&rgb[(size_t(y / factor) * width + x / factor) * 3], 3,
                  &canvas[(size_t(y) * canvasWidth + left + x) * 3]);
  if (left > 0)  // a grey edge either side: a white image stays apart from the canvas
    for (int y = 0; y < scaledHeight; ++y)
      for (const int x : {left - 1, left + scaledWidth})
        std::fill_n(&canvas[(size_t(y) * canvasWidth + x) * 3], 3, std::uint8_t(150));
  AnnotatedImage out;
  out.width = canvasWidth;
  out.height = scaledHeight + annotationHeight(annotation, canvasWidth);
  out.rgb = annotateImage(canvas, canvasWidth, scaledHeight, annotation);
  return out;
}
