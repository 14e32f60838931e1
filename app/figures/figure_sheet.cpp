#include "figures/figure_sheet.h"

#include <cairo-pdf.h>
#include <cairo.h>

#include <algorithm>
#include <functional>
#include <memory>
#include <stdexcept>
#include <system_error>

#include "figures/cairo_file.h"
#include "figures/cairo_text.h"

namespace fs = std::filesystem;

namespace {

using Surface = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;

int columnsFor(int panelCount) { return std::clamp(panelCount, 1, kSheetColumns); }

// 1. One panel: the image scaled to fit its box, centred; "(a) caption" below it.
void drawPanel(cairo_t* cr, double x, double y, cairo_surface_t* image, char letter,
               const std::string& caption) {
  const double w = cairo_image_surface_get_width(image), h = cairo_image_surface_get_height(image);
  const double scale = std::min(kSheetCell / w, kSheetImage / h);
  const double left = x + 0.5 * (kSheetCell - w * scale), top = y + (kSheetImage - h * scale);
  cairo_save(cr);
  cairo_translate(cr, left, top);
  cairo_scale(cr, scale, scale);
  cairo_set_source_surface(cr, image, 0, 0);
  cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_GOOD);
  cairo_paint(cr);
  cairo_restore(cr);
  cairo_set_source_rgb(cr, 0.6, 0.6, 0.6);  // a frame: white images stay apart from the page
  cairo_set_line_width(cr, 1);
  cairo_rectangle(cr, left - 0.5, top - 0.5, w * scale + 1, h * scale + 1);
  cairo_stroke(cr);
  const std::string label = std::string("(") + letter + ") ";
  const double labelWidth = textWidth(cr, label, 13, true);
  drawText(cr, x, y + kSheetImage + 4, label, 13, 0, true);
  double lineY = y + kSheetImage + 5;
  for (const std::string& line : wrapText(cr, caption, 12, kSheetCell - labelWidth, 3)) {
    drawText(cr, x + labelWidth, lineY, line, 12, 0.15);
    lineY += 16;
  }
}

void drawSheet(cairo_t* cr, const std::string& title, const std::vector<FigurePanel>& panels,
               const std::vector<Surface>& images) {
  const SheetSize size = figureSheetSize(int(panels.size()));
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_rectangle(cr, 0, 0, size.width, size.height);
  cairo_fill(cr);
  const auto titleLines = wrapText(cr, title, 15, size.width - 2 * kSheetMargin, 1);
  if (!titleLines.empty()) drawText(cr, kSheetMargin, kSheetMargin, titleLines[0], 15, 0, true);
  const int columns = columnsFor(int(panels.size()));
  for (size_t i = 0; i < panels.size(); ++i) {
    const int column = int(i) % columns, row = int(i) / columns;
    const double x = kSheetMargin + column * (kSheetCell + kSheetGap);
    const double y = kSheetMargin + kSheetTitle + row * (kSheetImage + kSheetCaption + kSheetGap);
    drawPanel(cr, x, y, images[i].get(), char('a' + i % 26), panels[i].caption);
  }
}

}  // namespace

SheetSize figureSheetSize(int panelCount) {
  const int columns = columnsFor(panelCount);
  const int rows = std::max(1, (panelCount + columns - 1) / columns);
  return {2 * kSheetMargin + columns * kSheetCell + (columns - 1) * kSheetGap,
          2 * kSheetMargin + kSheetTitle + rows * (kSheetImage + kSheetCaption) +
              (rows - 1) * kSheetGap};
}

std::vector<fs::path> writeFigureSheet(const fs::path& stem, const std::string& title,
                                       const std::vector<FigurePanel>& panels) {
  if (panels.empty()) throw std::runtime_error("a figure sheet needs at least one panel");
  if (panels.size() > 26) throw std::runtime_error("a figure sheet holds at most 26 panels (a-z)");
  std::vector<Surface> images;
  for (const FigurePanel& panel : panels) {
    Surface image(cairo_image_surface_create_from_png(panel.png.c_str()), &cairo_surface_destroy);
    if (cairo_surface_status(image.get()) != CAIRO_STATUS_SUCCESS)
      throw std::runtime_error("figure sheet: cannot read panel " + panel.png.string() + ": " +
                               cairo_status_to_string(cairo_surface_status(image.get())));
    const FigurePanel::Rect& c = panel.crop;
    const int w = cairo_image_surface_get_width(image.get()), h = cairo_image_surface_get_height(image.get());
    if (c.width > 0 && c.height > 0) {  // a part of it, clamped to the image
      const int x0 = std::clamp(c.x, 0, w - 1), y0 = std::clamp(c.y, 0, h - 1);
      const int cw = std::clamp(c.width, 1, w - x0), ch = std::clamp(c.height, 1, h - y0);
      Surface part(cairo_image_surface_create(CAIRO_FORMAT_RGB24, cw, ch), &cairo_surface_destroy);
      cairo_t* cr = cairo_create(part.get());
      cairo_set_source_surface(cr, image.get(), -x0, -y0);
      cairo_paint(cr);
      cairo_destroy(cr);
      image = std::move(part);
    }
    images.push_back(std::move(image));
  }
  const SheetSize size = figureSheetSize(int(panels.size()));
  const auto draw = [&](cairo_t* cr) { drawSheet(cr, title, panels, images); };
  const fs::path png = stem.string() + ".png", pdf = stem.string() + ".pdf";
  writeCairoFile(png, [&](const char*) {
    return cairo_image_surface_create(CAIRO_FORMAT_RGB24, size.width, size.height);
  }, draw, true);
  writeCairoFile(pdf, [&](const char* file) {
    return cairo_pdf_surface_create(file, size.width, size.height);
  }, draw, false);
  return {png, pdf};
}
