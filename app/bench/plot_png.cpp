#include "bench/plot_png.h"

#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "io/image_export.h"
#include "bench/plot_font.h"

namespace {

using Color = std::array<float, 3>;
const Color kBlack{0, 0, 0}, kGrid{0.88f, 0.88f, 0.88f}, kFrontier{0.1f, 0.1f, 0.1f};
// Colour-blind-safe series colours (Okabe-Ito), then greys.
const Color kSeries[] = {{0.0f, 0.45f, 0.70f}, {0.90f, 0.62f, 0.0f}, {0.0f, 0.62f, 0.45f},
                         {0.80f, 0.47f, 0.65f}, {0.84f, 0.37f, 0.0f}, {0.35f, 0.70f, 0.90f},
                         {0.94f, 0.89f, 0.26f}, {0.4f, 0.4f, 0.4f}};

std::string tickText(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// "Nice" linear ticks (1, 2, 5 x 10^k) covering [0, top].
std::vector<double> linearTicks(double top, double& axisTop) {
  const double raw = top / 5, magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = magnitude;
  for (double factor : {1.0, 2.0, 5.0, 10.0})
    if (factor * magnitude >= raw) { step = factor * magnitude; break; }
  axisTop = std::ceil(top / step) * step;
  std::vector<double> ticks;
  for (double t = 0; t <= axisTop * (1 + 1e-9); t += step) ticks.push_back(t);
  return ticks;
}

// Linear ticks at a 1, 2, 5 x 10^k step inside [low, high].
std::vector<double> rangeTicks(double low, double high) {
  double unused = 0;
  const std::vector<double> fromZero = linearTicks(high - low, unused);
  const double step = fromZero.size() > 1 ? fromZero[1] : 1;
  std::vector<double> ticks;
  for (double t = std::ceil(low / step) * step; t <= high + 1e-9 * step; t += step)
    ticks.push_back(std::fabs(t) < 1e-12 * step ? 0.0 : t);
  return ticks;
}

// Log ticks at 1, 2, 5 x 10^k inside [low, high]; at 1..9 x 10^k when that gives fewer
// than three.
std::vector<double> logTicks(double low, double high) {
  std::vector<double> ticks;
  for (const std::vector<double>& factors : {std::vector<double>{1, 2, 5},
                                             std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9}}) {
    ticks.clear();
    for (int k = int(std::floor(std::log10(low))); k <= int(std::ceil(std::log10(high))); ++k)
      for (double factor : factors) {
        const double t = factor * std::pow(10.0, k);
        if (t >= low && t <= high) ticks.push_back(t);
      }
    if (ticks.size() >= 3) break;
  }
  return ticks;
}

void marker(OIIO::ImageBuf& image, int x, int y, int series, int radius) {
  const Color& c = kSeries[size_t(series) % std::size(kSeries)];
  const int shape = series / int(std::size(kSeries)) + series % 3;  // vary shape too
  if (shape % 3 == 0) {
    OIIO::ImageBufAlgo::render_box(image, x - radius, y - radius, x + radius, y + radius, c, true);
  } else if (shape % 3 == 1) {  // diamond: filled rows
    for (int dy = -radius - 1; dy <= radius + 1; ++dy) {
      const int half = radius + 1 - std::abs(dy);
      OIIO::ImageBufAlgo::render_line(image, x - half, y + dy, x + half, y + dy, c);
    }
  } else {  // triangle
    for (int dy = -radius; dy <= radius; ++dy) {
      const int half = (dy + radius + 1) / 2 + 1;
      OIIO::ImageBufAlgo::render_line(image, x - half, y + dy, x + half, y + dy, c);
    }
  }
}

}  // namespace

std::vector<bool> paretoFrontier(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<bool> frontier(x.size(), true);
  for (size_t i = 0; i < x.size(); ++i)
    for (size_t j = 0; j < x.size() && frontier[i]; ++j)
      if (j != i && x[j] <= x[i] && y[j] <= y[i] && (x[j] < x[i] || y[j] < y[i]))
        frontier[i] = false;
  return frontier;
}

std::string writeScatterPlot(const std::filesystem::path& path, const PlotSpec& spec) {
  const PlotText text(spec.forceBitmapFont);

  // 1. The points that can be drawn (finite; log x needs x > 0) and the frontier, numbered
  //    left to right; the legend (series, then the frontier's list) sits right of the axes
  //    so it never hides a point.
  std::vector<const PlotPoint*> points, frontier;
  for (const PlotPoint& p : spec.points)
    if (std::isfinite(p.x) && std::isfinite(p.y) && (!spec.logX || p.x > 0) && (!spec.logY || p.y > 0))
      points.push_back(&p);
  for (const PlotPoint* p : points) if (p->frontier) frontier.push_back(p);
  std::sort(frontier.begin(), frontier.end(), [](auto a, auto b) { return a->x < b->x; });
  std::vector<std::string> frontierLines;
  for (size_t i = 0; i < frontier.size(); ++i) {
    char numbers[64];
    std::snprintf(numbers, sizeof numbers, " (%.3g, %.3g)", frontier[i]->x, frontier[i]->y);
    frontierLines.push_back(std::to_string(i + 1) + ". " + frontier[i]->label + numbers);
  }
  int legendWidth = text.width(spec.frontierCaption, 14) + 22;
  for (const std::string& name : spec.seriesNames) legendWidth = std::max(legendWidth, 22 + text.width(name, 14));
  for (const std::string& line : frontierLines) legendWidth = std::max(legendWidth, 4 + text.width(line, 13));
  const int W = spec.width + legendWidth + 24, H = spec.height;
  const int x0 = 96, x1 = spec.width - 24, y0 = H - 78, y1 = 56;
  OIIO::ImageBuf image(OIIO::ImageSpec(W, H, 3, OIIO::TypeDesc::FLOAT));
  const float white[3] = {1, 1, 1};
  OIIO::ImageBufAlgo::fill(image, white);

  // 2. Ranges and mappings.
  double xLow = 1, xHigh = 10, yLow = 0.1, yHigh = 1;
  if (!points.empty()) {
    xLow = xHigh = points[0]->x;
    yLow = yHigh = points[0]->y;
    for (const PlotPoint* p : points) {
      xLow = std::min(xLow, p->x);
      xHigh = std::max(xHigh, p->x);
      yLow = std::min(yLow, p->y);
      yHigh = std::max(yHigh, p->y);
    }
  }
  if (spec.logX) { xLow /= 1.25; xHigh *= 1.25; }
  else { const double pad = 0.05 * std::max(xHigh - xLow, 1e-9); xLow -= pad; xHigh += pad; }
  if (xHigh <= xLow) xHigh = xLow * 2 + 1;
  double yTop = 1, yBottom = 0;
  std::vector<double> yTicks;
  if (spec.logY) {
    yBottom = yLow / 1.25;
    yTop = std::max(yHigh * 1.25, yBottom * 2);
    yTicks = logTicks(yBottom, yTop);
  } else {
    yTicks = linearTicks(std::max(yHigh * 1.08, 1e-6), yTop);
  }
  auto px = [&](double x) {
    const double t = spec.logX ? (std::log(x) - std::log(xLow)) / (std::log(xHigh) - std::log(xLow))
                               : (x - xLow) / (xHigh - xLow);
    return x0 + int(std::lround(t * (x1 - x0)));
  };
  auto py = [&](double y) {
    const double t = spec.logY ? (std::log(y) - std::log(yBottom)) / (std::log(yTop) - std::log(yBottom))
                               : y / yTop;
    return y0 - int(std::lround(t * (y0 - y1)));
  };

  // 3. Grid, axes, ticks, labels.
  std::vector<double> xTicks;
  if (spec.logX) xTicks = logTicks(xLow, xHigh);
  else xTicks = rangeTicks(xLow, xHigh);
  for (double t : xTicks) {
    if (t < xLow || t > xHigh) continue;
    OIIO::ImageBufAlgo::render_line(image, px(t), y0, px(t), y1, kGrid);
    OIIO::ImageBufAlgo::render_line(image, px(t), y0, px(t), y0 + 5, kBlack);
    text.draw(image, px(t), y0 + 8, tickText(t), 15, kBlack, TextAlign::Center);
  }
  for (double t : yTicks) {
    OIIO::ImageBufAlgo::render_line(image, x0, py(t), x1, py(t), kGrid);
    OIIO::ImageBufAlgo::render_line(image, x0 - 5, py(t), x0, py(t), kBlack);
    text.draw(image, x0 - 8, py(t) - 8, tickText(t), 15, kBlack, TextAlign::Right);
  }
  OIIO::ImageBufAlgo::render_box(image, x0, y1, x1, y0, kBlack);
  text.draw(image, (x0 + x1) / 2, H - 34, spec.xLabel, 17, kBlack, TextAlign::Center);
  text.draw(image, 12, (y0 + y1) / 2, spec.yLabel, 17, kBlack, TextAlign::Center, /*vertical=*/true);
  text.draw(image, W / 2, 14, spec.title, 19, kBlack, TextAlign::Center);

  // 4. The frontier's line, every marker, the frontier's rings and numbers.
  for (size_t i = 1; i < frontier.size(); ++i)
    OIIO::ImageBufAlgo::render_line(image, px(frontier[i - 1]->x), py(frontier[i - 1]->y),
                                    px(frontier[i]->x), py(frontier[i]->y), kFrontier);
  if (spec.connectSeries)
    for (size_t series = 0; series < spec.seriesNames.size(); ++series) {
      std::vector<const PlotPoint*> line;
      for (const PlotPoint* p : points) if (p->series == int(series)) line.push_back(p);
      std::sort(line.begin(), line.end(), [](auto a, auto b) { return a->x < b->x; });
      const Color& c = kSeries[series % std::size(kSeries)];
      for (size_t i = 1; i < line.size(); ++i)
        OIIO::ImageBufAlgo::render_line(image, px(line[i - 1]->x), py(line[i - 1]->y),
                                        px(line[i]->x), py(line[i]->y), c);
    }
  for (const PlotPoint* p : points) marker(image, px(p->x), py(p->y), p->series, 4);
  for (size_t i = 0; i < frontier.size(); ++i) {
    const int fx = px(frontier[i]->x), fy = py(frontier[i]->y);
    OIIO::ImageBufAlgo::render_box(image, fx - 8, fy - 8, fx + 8, fy + 8, kFrontier);
    text.draw(image, fx + 9, fy - 26, std::to_string(i + 1), 14, kFrontier);
  }

  // 5. The legend.
  const int lx = x1 + 24;
  int ly = y1;
  for (size_t s = 0; s < spec.seriesNames.size(); ++s, ly += 20) {
    marker(image, lx + 8, ly + 8, int(s), 4);
    text.draw(image, lx + 22, ly, spec.seriesNames[s], 14, kBlack);
  }
  if (!frontier.empty()) {
    ly += 10;
    OIIO::ImageBufAlgo::render_line(image, lx, ly + 8, lx + 16, ly + 8, kFrontier);
    OIIO::ImageBufAlgo::render_box(image, lx + 2, ly + 2, lx + 14, ly + 14, kFrontier);
    text.draw(image, lx + 22, ly, spec.frontierCaption, 14, kBlack);
    ly += 22;
    for (const std::string& line : frontierLines) {
      text.draw(image, lx + 4, ly, line, 13, kFrontier);
      ly += 17;
    }
  }

  // 6. To 8-bit RGB, top row first (ImageBuf order), written atomically.
  std::vector<std::uint8_t> rgb(size_t(W) * H * 3);
  image.get_pixels(OIIO::ROI(0, W, 0, H, 0, 1, 0, 3), OIIO::TypeDesc::UINT8, rgb.data());
  writePng(path, rgb, W, H);
  return text.usesFont() ? "font " + text.fontName() : "built-in bitmap font (no font found)";
}
