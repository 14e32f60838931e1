#include "bench/plot_layout.h"

#include <algorithm>
#include <cmath>

namespace {

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

}  // namespace

double ChartAxis::at(double v) const {
  return log ? (std::log(v) - std::log(low)) / (std::log(high) - std::log(low))
             : (v - low) / (high - low);
}

ChartLayout chartLayout(const std::vector<double>& xs, const std::vector<double>& ys,
                        const std::vector<bool>& onFrontier, bool logX, bool logY) {
  ChartLayout l;
  const size_t n = std::min(xs.size(), ys.size());
  for (size_t i = 0; i < n; ++i)
    if (std::isfinite(xs[i]) && std::isfinite(ys[i]) && (!logX || xs[i] > 0) && (!logY || ys[i] > 0))
      l.drawable.push_back(i);
  for (size_t i : l.drawable) if (i < onFrontier.size() && onFrontier[i]) l.frontier.push_back(i);
  std::stable_sort(l.frontier.begin(), l.frontier.end(), [&](size_t a, size_t b) { return xs[a] < xs[b]; });

  double xLow = 1, xHigh = 10, yLow = 0.1, yHigh = 1;
  if (!l.drawable.empty()) {
    xLow = xHigh = xs[l.drawable[0]];
    yLow = yHigh = ys[l.drawable[0]];
    for (size_t i : l.drawable) {
      xLow = std::min(xLow, xs[i]), xHigh = std::max(xHigh, xs[i]);
      yLow = std::min(yLow, ys[i]), yHigh = std::max(yHigh, ys[i]);
    }
  }
  l.x.log = logX;
  if (logX) { xLow /= 1.25; xHigh *= 1.25; }
  else { const double pad = 0.05 * std::max(xHigh - xLow, 1e-9); xLow -= pad; xHigh += pad; }
  if (xHigh <= xLow) xHigh = xLow * 2 + 1;
  l.x.low = xLow, l.x.high = xHigh;
  l.x.ticks = logX ? logTicks(xLow, xHigh) : rangeTicks(xLow, xHigh);

  l.y.log = logY;
  if (logY) {
    l.y.low = yLow / 1.25;
    l.y.high = std::max(yHigh * 1.25, l.y.low * 2);
    l.y.ticks = logTicks(l.y.low, l.y.high);
  } else {
    l.y.low = 0;
    l.y.ticks = linearTicks(std::max(yHigh * 1.08, 1e-6), l.y.high);
  }
  return l;
}

MarkerOutline markerOutline(MarkerShape shape) {
  MarkerOutline m;
  switch (shape) {
    case MarkerShape::Square: m.vertices = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}; break;
    case MarkerShape::Diamond: m.vertices = {{0, -1.3}, {1.3, 0}, {0, 1.3}, {-1.3, 0}}; break;
    case MarkerShape::Triangle: m.vertices = {{0, -1.2}, {1.2, 1}, {-1.2, 1}}; break;
    case MarkerShape::Circle: m.circle = true, m.radius = 1.1; break;
    case MarkerShape::TriangleDown: m.vertices = {{0, 1.2}, {1.2, -1}, {-1.2, -1}}; break;
  }
  return m;
}
