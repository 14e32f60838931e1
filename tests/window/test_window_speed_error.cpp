// The speed-vs-error panel's pure parts (app/window/panels/ui_speed_error.h): reading bench's CSV by its
// header, the Pareto frontier against a brute-force dominance check, and the match of the
// current pipeline parameters. No window needed.
#include <gtest/gtest.h>

#include <algorithm>

#include "bench/bench_output.h"
#include "core/pipeline.h"
#include "window/panels/ui_speed_error.h"

namespace {

std::string header() {
  std::string line;
  for (const std::string& c : benchCsvColumns()) line += (line.empty() ? "" : ",") + c;
  return line + "\n";
}

// A row in bench_output.cpp's column order, with the fields the panel reads set.
std::string row(const std::string& config, const std::string& method, const std::string& search,
                const std::string& layers, int rays, int map, bool deferred, bool filter,
                double ms, double error) {
  std::vector<std::string> f(benchCsvColumns().size());
  const auto cols = benchCsvColumns();
  auto set = [&](const std::string& name, const std::string& v) {
    for (size_t i = 0; i < cols.size(); ++i) if (cols[i] == name) f[i] = v;
  };
  set("setup", "\"cube, 256x256\"");  // quoted, with a comma
  set("config", config);
  set("method", method);
  set("search", search);
  set("layers", layers);
  set("rays_per_side", rays ? std::to_string(rays) : "");
  set("shadow_map", std::to_string(map));
  set("deferred", deferred ? "1" : "0");
  set("filter", filter ? "1" : "0");
  set("ms_median", std::to_string(ms));
  set("mean_abs_error_in_shadow", std::to_string(error));
  std::string line;
  for (size_t i = 0; i < f.size(); ++i) line += (i ? "," : "") + f[i];
  return line + "\n";
}

}  // namespace

TEST(SpeedErrorPanel, ParsesBenchColumnsAndQuotedFields) {
  const std::string text = header() + row("hard", "hard_shadow", "", "", 0, 512, true, true, 2, 0.2) +
                           row("hier 2x2", "monte_carlo", "hierarchical", "two", 2, 512, true, true, 8.5, 0.05);
  std::vector<SpeedErrorPoint> points;
  ASSERT_EQ(parseSpeedErrorCsv(text, points), "");
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[0].setup, "cube, 256x256");
  EXPECT_EQ(points[1].search, "hierarchical");
  EXPECT_EQ(points[1].layers, "two");
  EXPECT_EQ(points[1].rays, 2);
  EXPECT_DOUBLE_EQ(points[1].msMedian, 8.5);
  EXPECT_DOUBLE_EQ(points[1].meanAbsErrorInShadow, 0.05);
  EXPECT_NE(parseSpeedErrorCsv("a,b\n1,2\n", points), "");  // not a bench CSV
}

TEST(SpeedErrorPanel, FrontierIsExactlyTheNonDominatedPoints) {
  std::vector<SpeedErrorPoint> points;
  const double data[][2] = {{1, 0.5}, {2, 0.3}, {3, 0.4}, {4, 0.1}, {5, 0.1}, {2.5, 0.3}, {10, 0.01}, {0.5, 0.9}};
  for (auto& d : data) {
    SpeedErrorPoint p;
    p.msMedian = d[0];
    p.meanAbsErrorInShadow = d[1];
    points.push_back(p);
  }
  const std::vector<size_t> frontier = paretoFrontier(points);
  for (size_t i = 0; i < points.size(); ++i) {
    bool dominated = false;  // brute force: some other point no worse in both, better in one
    for (size_t j = 0; j < points.size(); ++j)
      dominated |= j != i && points[j].msMedian <= points[i].msMedian &&
                   points[j].meanAbsErrorInShadow <= points[i].meanAbsErrorInShadow &&
                   (points[j].msMedian < points[i].msMedian ||
                    points[j].meanAbsErrorInShadow < points[i].meanAbsErrorInShadow);
    const bool on = std::find(frontier.begin(), frontier.end(), i) != frontier.end();
    EXPECT_EQ(on, !dominated) << "point " << i;
  }
  EXPECT_EQ(frontier.size(), 5u);  // 0.5, 1, 2, 4, 10 ms
}

TEST(SpeedErrorPanel, MatchesTheCurrentPipelineParameters) {
  const std::string text = header() + row("hard", "hard_shadow", "", "", 0, 512, true, true, 2, 0.2) +
                           row("a", "monte_carlo", "hierarchical", "two", 2, 512, true, true, 8, 0.05) +
                           row("b", "monte_carlo", "hierarchical", "two", 3, 512, true, true, 12, 0.03);
  std::vector<SpeedErrorPoint> points;
  ASSERT_EQ(parseSpeedErrorCsv(text, points), "");
  Pipeline pipeline;
  for (const char* s : {"trace.search=hierarchical", "light.layers=two", "trace.rays=3",
                        "light.resolution=512", "trace.deferred=true", "filter.enabled=true"})
    ASSERT_EQ(pipeline.set(s), "") << s;
  EXPECT_EQ(matchingPoint(points, pipelineConfigOf(pipeline)), 2);
  ASSERT_EQ(pipeline.set("trace.deferred=false"), "");
  EXPECT_EQ(matchingPoint(points, pipelineConfigOf(pipeline)), -1);  // no exact match
}
