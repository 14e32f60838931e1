#include "bench/plot.h"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <system_error>

#include "bench/plot_layout.h"
#include "figures/cairo_file.h"

namespace {

using Color = std::array<double, 3>;
const Color kBlack{0, 0, 0}, kGrid{0.88, 0.88, 0.88}, kFrontier{0.1, 0.1, 0.1};
const char* kFont = "DejaVu Sans";

std::string tickText(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

enum class Align { Left, Center, Right };

// Text whose top edge is at y (as the layout below measures it).
void text(cairo_t* cr, double x, double y, const std::string& s, double size, const Color& c,
          Align align = Align::Left, bool vertical = false) {
  cairo_save(cr);
  cairo_select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_set_source_rgb(cr, c[0], c[1], c[2]);
  cairo_text_extents_t extents;
  cairo_text_extents(cr, s.c_str(), &extents);
  cairo_translate(cr, x, y);
  if (vertical) cairo_rotate(cr, -M_PI / 2);
  const double shift = align == Align::Left ? 0 : align == Align::Center ? extents.x_advance / 2
                                                                         : extents.x_advance;
  cairo_move_to(cr, -shift, vertical ? size * 0.8 : size * 0.8);
  cairo_show_text(cr, s.c_str());
  cairo_new_path(cr);  // no current point left for the next shape to join
  cairo_restore(cr);
}

double textWidth(cairo_t* cr, const std::string& s, double size) {
  cairo_save(cr);
  cairo_select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_text_extents_t extents;
  cairo_text_extents(cr, s.c_str(), &extents);
  cairo_restore(cr);
  return extents.x_advance;
}

void line(cairo_t* cr, double xa, double ya, double xb, double yb, const Color& c, double width = 1) {
  cairo_set_source_rgb(cr, c[0], c[1], c[2]);
  cairo_set_line_width(cr, width);
  cairo_move_to(cr, xa, ya);
  cairo_line_to(cr, xb, yb);
  cairo_stroke(cr);
}

// The series' shape and colour (seriesStyle), so colour is not the only cue; the outline
// is the chart layout's (plot_layout.h), as the window draws it.
void marker(cairo_t* cr, double x, double y, int series, double r) {
  const SeriesStyle style = seriesStyle(series);
  cairo_set_source_rgb(cr, style.r, style.g, style.b);
  const MarkerOutline outline = markerOutline(style.shape);
  if (outline.circle) {
    cairo_new_sub_path(cr);
    cairo_arc(cr, x, y, r * outline.radius, 0, 2 * M_PI);
  } else {
    for (size_t i = 0; i < outline.vertices.size(); ++i)
      (i == 0 ? cairo_move_to : cairo_line_to)(cr, x + r * outline.vertices[i][0], y + r * outline.vertices[i][1]);
    cairo_close_path(cr);
  }
  cairo_fill(cr);
}

struct Layout {
  ChartLayout chart;  // ranges, ticks, drawable points, frontier order (plot_layout.h)
  std::vector<const PlotPoint*> points, frontier;  // drawable; frontier by increasing x
  std::vector<std::string> frontierLines;
  double width = 0, height = 0;
};

// 1. The chart's layout (the points that can be drawn, the frontier numbered left to right,
//    the axes) and the page: the legend sits right of the axes so it never hides a point.
Layout layout(const PlotSpec& spec) {
  Layout l;
  std::vector<double> xs, ys;
  std::vector<bool> onFrontier;
  for (const PlotPoint& p : spec.points) xs.push_back(p.x), ys.push_back(p.y), onFrontier.push_back(p.frontier);
  l.chart = chartLayout(xs, ys, onFrontier, spec.logX, spec.logY);
  for (size_t i : l.chart.drawable) l.points.push_back(&spec.points[i]);
  for (size_t i : l.chart.frontier) l.frontier.push_back(&spec.points[i]);
  for (size_t i = 0; i < l.frontier.size(); ++i) {
    char numbers[64];
    std::snprintf(numbers, sizeof numbers, " (%.3g, %.3g)", l.frontier[i]->x, l.frontier[i]->y);
    l.frontierLines.push_back(std::to_string(i + 1) + ". " + l.frontier[i]->label + numbers);
  }
  cairo_surface_t* scratch = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 1, 1);
  cairo_t* cr = cairo_create(scratch);
  double legend = textWidth(cr, spec.frontierCaption, 14) + 22;
  for (const std::string& name : spec.seriesNames) legend = std::max(legend, 22 + textWidth(cr, name, 14));
  for (const std::string& s : l.frontierLines) legend = std::max(legend, 4 + textWidth(cr, s, 13));
  cairo_destroy(cr);
  cairo_surface_destroy(scratch);
  l.width = std::ceil(spec.width + legend + 24);
  l.height = spec.height;
  return l;
}

void drawPlot(cairo_t* cr, const PlotSpec& spec, const Layout& l) {
  const double W = l.width, H = l.height;
  const PlotBox box = plotAxesBox(spec);
  const double x0 = box.left, x1 = box.right, y0 = box.bottom, y1 = box.top;
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);

  // 2. The mappings of the layout's axes onto this page's box.
  const ChartAxis &xAxis = l.chart.x, &yAxis = l.chart.y;
  auto px = [&](double x) { return x0 + xAxis.at(x) * (x1 - x0); };
  auto py = [&](double y) { return y0 - yAxis.at(y) * (y0 - y1); };

  // 3. Grid, axes, ticks, labels.
  for (double t : xAxis.ticks) {
    line(cr, px(t), y0, px(t), y1, kGrid);
    line(cr, px(t), y0, px(t), y0 + 5, kBlack);
    text(cr, px(t), y0 + 8, tickText(t), 15, kBlack, Align::Center);
  }
  for (double t : yAxis.ticks) {
    line(cr, x0, py(t), x1, py(t), kGrid);
    line(cr, x0 - 5, py(t), x0, py(t), kBlack);
    text(cr, x0 - 8, py(t) - 8, tickText(t), 15, kBlack, Align::Right);
  }
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 1);
  cairo_rectangle(cr, x0, y1, x1 - x0, y0 - y1);
  cairo_stroke(cr);
  text(cr, (x0 + x1) / 2, H - 34, spec.xLabel, 17, kBlack, Align::Center);
  text(cr, 12, (y0 + y1) / 2, spec.yLabel, 17, kBlack, Align::Center, /*vertical=*/true);
  text(cr, W / 2, 14, spec.title, 19, kBlack, Align::Center);

  // 4. The frontier's line, the series' lines, every marker, the frontier's rings and numbers.
  for (size_t i = 1; i < l.frontier.size(); ++i)
    line(cr, px(l.frontier[i - 1]->x), py(l.frontier[i - 1]->y), px(l.frontier[i]->x),
         py(l.frontier[i]->y), kFrontier, 1.5);
  if (spec.connectSeries)
    for (size_t series = 0; series < spec.seriesNames.size(); ++series) {
      std::vector<const PlotPoint*> run;
      for (const PlotPoint* p : l.points) if (p->series == int(series)) run.push_back(p);
      std::sort(run.begin(), run.end(), [](auto a, auto b) { return a->x < b->x; });
      for (size_t i = 1; i < run.size(); ++i)
        line(cr, px(run[i - 1]->x), py(run[i - 1]->y), px(run[i]->x), py(run[i]->y),
             Color{seriesStyle(int(series)).r, seriesStyle(int(series)).g, seriesStyle(int(series)).b}, 1.5);
    }
  for (const PlotPoint* p : l.points) marker(cr, px(p->x), py(p->y), p->series, 4);
  for (size_t i = 0; i < l.frontier.size(); ++i) {
    const double fx = px(l.frontier[i]->x), fy = py(l.frontier[i]->y);
    cairo_set_source_rgb(cr, kFrontier[0], kFrontier[1], kFrontier[2]);
    cairo_set_line_width(cr, 1.2);
    cairo_new_sub_path(cr);
    cairo_arc(cr, fx, fy, 8, 0, 2 * M_PI);
    cairo_stroke(cr);
    text(cr, fx + 9, fy - 26, std::to_string(i + 1), 14, kFrontier);
  }

  // 5. The legend.
  const double lx = x1 + 24;
  double ly = y1;
  for (size_t s = 0; s < spec.seriesNames.size(); ++s, ly += 20) {
    marker(cr, lx + 8, ly + 8, int(s), 4);
    text(cr, lx + 22, ly, spec.seriesNames[s], 14, kBlack);
  }
  if (!l.frontier.empty()) {
    ly += 10;
    line(cr, lx, ly + 8, lx + 16, ly + 8, kFrontier, 1.5);
    cairo_new_sub_path(cr);
    cairo_arc(cr, lx + 8, ly + 8, 6, 0, 2 * M_PI);
    cairo_stroke(cr);
    text(cr, lx + 22, ly, spec.frontierCaption, 14, kBlack);
    ly += 22;
    for (const std::string& s : l.frontierLines) {
      text(cr, lx + 4, ly, s, 13, kFrontier);
      ly += 17;
    }
  }
}

}  // namespace

std::vector<std::filesystem::path> writePlot(const std::filesystem::path& stem, const PlotSpec& spec) {
  const Layout l = layout(spec);
  const auto png = std::filesystem::path(stem.string() + ".png");
  const auto svg = std::filesystem::path(stem.string() + ".svg");
  const auto pdf = std::filesystem::path(stem.string() + ".pdf");
  const auto draw = [&](cairo_t* cr) { drawPlot(cr, spec, l); };
  writeCairoFile(png, [&](const char*) {
    return cairo_image_surface_create(CAIRO_FORMAT_RGB24, int(l.width), int(l.height));
  }, draw, true);
  writeCairoFile(svg, [&](const char* file) {
    return cairo_svg_surface_create(file, l.width, l.height);
  }, draw, false);
  writeCairoFile(pdf, [&](const char* file) {
    return cairo_pdf_surface_create(file, l.width, l.height);
  }, draw, false);
  return {png, svg, pdf};
}

PlotBox plotAxesBox(const PlotSpec& spec) {
  return {96, double(spec.width) - 24, double(spec.height) - 78, 56};
}

SeriesStyle seriesStyle(int series) {
  // Okabe-Ito (colour-blind safe) with black for its vermillion, which read as a second
  // orange, and a darker yellow that shows on white; then grey.
  static const SeriesStyle first[] = {
      {0.0, 0.45, 0.70, MarkerShape::Square},     {0.90, 0.62, 0.0, MarkerShape::Diamond},
      {0.0, 0.62, 0.45, MarkerShape::Triangle},   {0.80, 0.47, 0.65, MarkerShape::Circle},
      {0.0, 0.0, 0.0, MarkerShape::TriangleDown}, {0.35, 0.70, 0.90, MarkerShape::Circle},
      {0.80, 0.72, 0.0, MarkerShape::Square},     {0.55, 0.55, 0.55, MarkerShape::Triangle}};
  constexpr int kColours = int(std::size(first)), kShapes = 5;
  const int index = series < 0 ? 0 : series;
  SeriesStyle style = first[index % kColours];
  // Past eight: the same colours in the next shapes, so (colour, shape) repeats only after 40.
  style.shape = MarkerShape((int(style.shape) + index / kColours) % kShapes);
  return style;
}

std::string methodDisplayName(const std::string& method) {
  if (method == "filter") return "Monte Carlo";
  if (method == "trace") return "Monte Carlo (unfiltered)";
  if (method == "hard_shadow") return "hard shadow";
  if (method == "pcss") return "PCSS";
  if (method == "ssm") return "SSM";
  if (method == "raster4d") return "raster4d (exact)";
  if (method == "reference") return "reference (Embree, CPU)";
  return method;
}

std::string seriesLegend(const std::string& method, const std::string& family) {
  const std::string name = methodDisplayName(method);
  if (family.empty() || family == method || family == name) return name;
  return name + ": " + family;
}
