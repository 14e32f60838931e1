// The window's speed-vs-error panel lays its chart out with the report's layout
// (bench/plot_layout.h): same ranges, ticks and frontier as chartLayout over the points'
// time and error, log on both axes, the frontier the Pareto one (bench/pareto.h).
#include <gtest/gtest.h>

#include "bench/pareto.h"
#include "bench/plot_layout.h"
#include "window/panels/ui_speed_error.h"

TEST(SpeedErrorChart, PanelUsesTheSharedLayout) {
  std::vector<BenchResult> results(4);
  const double ms[] = {2, 20, 5, 40}, error[] = {0.08, 0.01, 0.05, 0.02};
  for (size_t i = 0; i < results.size(); ++i) results[i].msMedian = ms[i], results[i].error.meanAbsInShadow = error[i];
  std::vector<const BenchResult*> points;
  for (const BenchResult& r : results) points.push_back(&r);
  const ChartLayout panel = speedErrorChartLayout(points);
  // By hand: x [1.6, 50], y [0.008, 0.1]; point 3 (40 ms, 0.02) is beaten by point 1.
  EXPECT_DOUBLE_EQ(panel.x.low, 1.6);
  EXPECT_DOUBLE_EQ(panel.x.high, 50);
  EXPECT_DOUBLE_EQ(panel.y.low, 0.008);
  EXPECT_DOUBLE_EQ(panel.y.high, 0.1);
  EXPECT_EQ(panel.frontier, (std::vector<size_t>{0, 2, 1}));
  const ChartLayout shared = chartLayout({2, 20, 5, 40}, {0.08, 0.01, 0.05, 0.02},
                                         paretoFrontier({2, 20, 5, 40}, {0.08, 0.01, 0.05, 0.02}), true, true);
  EXPECT_EQ(panel.x.ticks, shared.x.ticks);
  EXPECT_EQ(panel.y.ticks, shared.y.ticks);
  EXPECT_EQ(panel.drawable, shared.drawable);
}
