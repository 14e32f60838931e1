// The speed-vs-error chart's one layout (bench/plot_layout.h) on inputs whose ranges and
// ticks are known by hand, and the report's cairo back end drawing its grid where the layout
// says (the window's back end: tests/window/test_speed_error_chart.cpp).
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <unistd.h>

#include "bench/plot.h"
#include "bench/plot_layout.h"

namespace {

void expectTicks(const std::vector<double>& got, const std::vector<double>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-12 * want[i]) << i;
}

}  // namespace

TEST(PlotLayout, LogAxesWidenByAQuarterAndTickAtOneTwoFive) {
  // x 1..100 -> [0.8, 125]; y 0.01..0.1 -> [0.008, 0.125].
  const ChartLayout l = chartLayout({1, 10, 100}, {0.1, 0.05, 0.01}, {}, true, true);
  EXPECT_DOUBLE_EQ(l.x.low, 0.8);
  EXPECT_DOUBLE_EQ(l.x.high, 125);
  EXPECT_DOUBLE_EQ(l.y.low, 0.008);
  EXPECT_DOUBLE_EQ(l.y.high, 0.125);
  expectTicks(l.x.ticks, {1, 2, 5, 10, 20, 50, 100});
  expectTicks(l.y.ticks, {0.01, 0.02, 0.05, 0.1});
  // 10 is the geometric middle of [0.8, 125] (12.5 x either way).
  EXPECT_NEAR(l.x.at(10), 0.5, 1e-12);
  EXPECT_NEAR(l.x.at(0.8), 0, 1e-12);
  EXPECT_NEAR(l.x.at(125), 1, 1e-12);
  EXPECT_NEAR(l.y.at(std::sqrt(0.008 * 0.125)), 0.5, 1e-12);
}

TEST(PlotLayout, NarrowLogRangeSpansTwiceAndFallsBackToEveryDigit) {
  // One y value 3: [2.4, max(3.75, 4.8)]; 1, 2, 5 x 10^k gives nothing inside, 1..9 gives 3, 4.
  const ChartLayout l = chartLayout({4, 4}, {3, 3}, {}, true, true);
  EXPECT_DOUBLE_EQ(l.y.low, 2.4);
  EXPECT_DOUBLE_EQ(l.y.high, 4.8);
  expectTicks(l.y.ticks, {3, 4});
  // x [3.2, 5]: 1, 2, 5 gives only 5; 1..9 gives 4, 5.
  expectTicks(l.x.ticks, {4, 5});
}

TEST(PlotLayout, LinearAxes) {
  // y from 0 to the first 0.2 step at or above 1.08 x 0.5 = 0.54; x [0, 10] padded by 0.5,
  // a step of 5 (11 / 5 = 2.2 rounds up to 5 among 1, 2, 5).
  const ChartLayout l = chartLayout({0, 10}, {0.5, 0.25}, {}, false, false);
  EXPECT_DOUBLE_EQ(l.y.low, 0);
  EXPECT_NEAR(l.y.high, 0.6, 1e-12);
  expectTicks(l.y.ticks, {0, 0.2, 0.4, 0.6});
  EXPECT_DOUBLE_EQ(l.x.low, -0.5);
  EXPECT_DOUBLE_EQ(l.x.high, 10.5);
  expectTicks(l.x.ticks, {0, 5, 10});
  EXPECT_NEAR(l.x.at(5), 0.5, 1e-12);
  EXPECT_NEAR(l.y.at(0.3), 0.5, 1e-12);
}

TEST(PlotLayout, DrawablePointsAndFrontierOrder) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = INFINITY;
  //                          0    1   2    3    4    5
  const std::vector<double> xs{8, 2, nan, 0, 5, 1};
  const std::vector<double> ys{1, 3, 1, 1, inf, 0.5};
  const std::vector<bool> frontier{true, true, true, true, true, false};
  const ChartLayout l = chartLayout(xs, ys, frontier, true, true);
  EXPECT_EQ(l.drawable, (std::vector<size_t>{0, 1, 5}));  // NaN, x = 0 on log, inf left out
  EXPECT_EQ(l.frontier, (std::vector<size_t>{1, 0}));     // increasing x
  // Ranges from the drawable points alone: x 1..8, y 0.5..3.
  EXPECT_DOUBLE_EQ(l.x.low, 0.8);
  EXPECT_DOUBLE_EQ(l.x.high, 10);
  EXPECT_DOUBLE_EQ(l.y.low, 0.4);
  EXPECT_DOUBLE_EQ(l.y.high, 3.75);
  // On linear axes x = 0 is drawable.
  EXPECT_EQ(chartLayout(xs, ys, frontier, false, false).drawable, (std::vector<size_t>{0, 1, 3, 5}));
}

TEST(PlotLayout, MarkerOutlinesAreClosedShapesAroundTheCentre) {
  for (MarkerShape shape : {MarkerShape::Square, MarkerShape::Diamond, MarkerShape::Triangle,
                            MarkerShape::Circle, MarkerShape::TriangleDown}) {
    const MarkerOutline m = markerOutline(shape);
    if (m.circle) {
      EXPECT_GT(m.radius, 0);
      continue;
    }
    ASSERT_GE(m.vertices.size(), 3u);
    // Inside a 2.6 r box, the centre strictly inside (every edge turns the same way around
    // it), and an area of at least a unit square's quarter.
    double area = 0;
    int positive = 0, negative = 0;
    for (size_t i = 0; i < m.vertices.size(); ++i) {
      const auto& a = m.vertices[i];
      const auto& b = m.vertices[(i + 1) % m.vertices.size()];
      const double cross = a[0] * b[1] - b[0] * a[1];  // edge a -> b against the centre
      area += cross / 2;
      if (cross > 0) ++positive;
      if (cross < 0) ++negative;
      EXPECT_LE(std::max(std::fabs(a[0]), std::fabs(a[1])), 1.3);
    }
    EXPECT_TRUE(positive == 0 || negative == 0) << int(shape);
    EXPECT_EQ(positive + negative, int(m.vertices.size())) << int(shape);
    EXPECT_GT(std::fabs(area), 1.0) << int(shape);
  }
  EXPECT_NE(markerOutline(MarkerShape::Triangle).vertices[0][1],
            markerOutline(MarkerShape::TriangleDown).vertices[0][1]);
}

// The cairo back end draws a grid line at every tick the layout gives, and none halfway
// between two: a row of the PNG inside the axes' box, away from the points.
TEST(PlotLayout, CairoChartDrawsTheLayoutsGrid) {
  PlotSpec spec;
  spec.title = "t";
  spec.xLabel = "x";
  spec.yLabel = "y";
  spec.seriesNames = {"a"};
  spec.logX = true;
  spec.logY = true;
  spec.points = {{1, 0.01, 0, "p", false}, {100, 0.1, 0, "q", false}};
  const auto stem = std::filesystem::temp_directory_path() / ("plot_layout_" + std::to_string(::getpid()));
  const auto files = writePlot(stem, spec);
  auto input = OIIO::ImageInput::open(files[0].string());
  ASSERT_TRUE(input);
  const OIIO::ImageSpec& image = input->spec();
  std::vector<unsigned char> pixels(size_t(image.width) * image.height * image.nchannels);
  ASSERT_TRUE(input->read_image(0, 0, 0, image.nchannels, OIIO::TypeDesc::UINT8, pixels.data()));
  input->close();
  for (const auto& f : files) std::filesystem::remove(f);

  std::vector<double> xs, ys;
  for (const PlotPoint& p : spec.points) xs.push_back(p.x), ys.push_back(p.y);
  const ChartLayout l = chartLayout(xs, ys, {}, true, true);
  const PlotBox box = plotAxesBox(spec);
  // A row a third of the way up (the points sit at the box's corners, the legend right of it).
  const int row = int(box.bottom - 0.37 * (box.bottom - box.top));
  auto darkest = [&](double x) {  // the darkest red value within a pixel of x on that row
    int value = 255;
    for (int c = int(std::floor(x)) - 1; c <= int(std::floor(x)) + 1; ++c)
      value = std::min<int>(value, pixels[(size_t(row) * image.width + c) * image.nchannels]);
    return value;
  };
  auto column = [&](double v) { return box.left + l.x.at(v) * (box.right - box.left); };
  ASSERT_EQ(l.x.ticks.size(), 7u);
  for (size_t i = 0; i < l.x.ticks.size(); ++i) {
    EXPECT_LT(darkest(column(l.x.ticks[i])), 250) << "no grid line at tick " << l.x.ticks[i];
    if (i + 1 < l.x.ticks.size()) {
      EXPECT_EQ(darkest(column(std::sqrt(l.x.ticks[i] * l.x.ticks[i + 1]))), 255)
          << "a line between " << l.x.ticks[i] << " and " << l.x.ticks[i + 1];
    }
  }
}
