// The speed-vs-error charts (bench/plot.h, the window's panel): every series its own marker,
// no two alike at a glance, and the legend says the method's name before its configuration.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>

#include "bench/plot.h"

namespace {

double colourDistance(const SeriesStyle& a, const SeriesStyle& b) {
  return std::sqrt((a.r - b.r) * (a.r - b.r) + (a.g - b.g) * (a.g - b.g) + (a.b - b.b) * (a.b - b.b));
}

}  // namespace

TEST(PlotStyles, FirstFortySeriesAreDistinctAndNoTwoLookAlike) {
  std::set<std::pair<std::array<double, 3>, int>> seen;
  for (int i = 0; i < 40; ++i) {
    const SeriesStyle s = seriesStyle(i);
    EXPECT_TRUE(seen.insert({{s.r, s.g, s.b}, int(s.shape)}).second) << "series " << i;
  }
  // Among the first eight (a default bench has 11 families; the window's panel a handful),
  // two markers of one shape differ clearly in colour: orange and vermillion diamonds did not.
  for (int i = 0; i < 8; ++i)
    for (int j = i + 1; j < 8; ++j)
      if (seriesStyle(i).shape == seriesStyle(j).shape) {
        EXPECT_GT(colourDistance(seriesStyle(i), seriesStyle(j)), 0.45) << i << " and " << j;
      }
  // Past eight, a repeated colour comes with another shape.
  for (int i = 0; i < 8; ++i) EXPECT_NE(seriesStyle(i).shape, seriesStyle(i + 8).shape) << i;
}

TEST(PlotStyles, LegendNamesTheMethodThenTheConfiguration) {
  EXPECT_EQ(seriesLegend("filter", "hierarchical 2L"), "Monte Carlo: hierarchical 2L");
  EXPECT_EQ(seriesLegend("trace", "hierarchical 2L unfiltered"),
            "Monte Carlo (unfiltered): hierarchical 2L unfiltered");
  EXPECT_EQ(seriesLegend("pcss", "pcss"), "PCSS");
  EXPECT_EQ(seriesLegend("ssm", "ssm"), "SSM");
  EXPECT_EQ(seriesLegend("hard_shadow", ""), "hard shadow");
  EXPECT_NE(seriesLegend("filter", "linear 2L"), seriesLegend("filter", "hierarchical 2L"));
}
