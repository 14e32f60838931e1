// The speed-against-error chart's layout, drawn by two back ends: the report's cairo charts
// (bench/plot.cpp: PNG, SVG, PDF) and the window's "Speed vs error" panel
// (window/panels/ui_speed_error.cpp, ImDrawList). Both take from here the axes' ranges and
// ticks, which points can be drawn, the Pareto frontier's order and every marker's outline,
// and add only what a back end owns: pixels, fonts, colours on white or on dark.
#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include "bench/plot.h"

struct ChartAxis {
  bool log = true;
  double low = 1, high = 10;   // the axis' ends, in data units (low < high)
  std::vector<double> ticks;   // grid lines, inside [low, high], increasing
  // 0 at `low`, 1 at `high`: linear in log(v) on a log axis, in v on a linear one.
  double at(double v) const;
};

struct ChartLayout {
  ChartAxis x, y;
  std::vector<size_t> drawable;  // indices of the points drawn: finite, and > 0 on a log axis
  std::vector<size_t> frontier;  // the drawable points flagged as frontier, by increasing x
};

// The chart of points (xs[i], ys[i]); onFrontier[i] marks the Pareto frontier (may be empty:
// none). Ranges:
//  - log axis: the points' range widened by 1.25x on each side; a log y axis spans 2x at
//    least; ticks at 1, 2, 5 x 10^k, or 1..9 x 10^k where that gives fewer than three;
//  - linear x: the range padded by 5% of its width, ticks at a 1, 2, 5 x 10^k step;
//  - linear y: from 0 to the first tick step (1, 2, 5 x 10^k, five steps) at or above 1.08x
//    the largest value.
// With no drawable point: x [1, 10], y [0.1, 1] before the widening.
ChartLayout chartLayout(const std::vector<double>& xs, const std::vector<double>& ys,
                        const std::vector<bool>& onFrontier, bool logX, bool logY);

// A marker's outline around its centre in units of its size r (y down, as both back ends
// draw): a polygon, or a circle of `radius`.
struct MarkerOutline {
  bool circle = false;
  double radius = 0;
  std::vector<std::array<double, 2>> vertices;
};
MarkerOutline markerOutline(MarkerShape shape);
