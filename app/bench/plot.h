// The report's charts (`penumbra bench`): the speed-against-error scatter (one marker per
// configuration, coloured by series, the Pareto frontier drawn as a line through its points,
// numbered and listed in the legend) and the error curves of the setup sweeps (a line per
// series). Drawn with cairo and written as PNG, SVG and PDF.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

struct PlotPoint {
  double x = 0, y = 0;
  int series = 0;         // index into PlotSpec::seriesNames (colour and marker)
  std::string label;      // listed for frontier points
  bool frontier = false;  // on the Pareto frontier: ringed, joined, numbered
};

struct PlotSpec {
  std::string title, xLabel, yLabel;
  std::vector<std::string> seriesNames;
  std::vector<PlotPoint> points;
  std::string frontierCaption = "Pareto frontier (x, y):";
  bool logX = true;
  bool logY = false;
  bool connectSeries = false;  // a line through each series' points, in x order (sweeps)
  int width = 1000, height = 680;  // the axes' area; the legend widens the page
};

// The axes' box on the page, in pixels (y down): the chart layout's (plot_layout.h) 0..1 map
// onto [left, right] and [bottom, top].
struct PlotBox { double left, right, bottom, top; };
PlotBox plotAxesBox(const PlotSpec& spec);

// Writes `stem`.png, .svg and .pdf (each atomically: a temporary file renamed); returns
// their paths. Throws std::runtime_error naming the file it cannot write.
std::vector<std::filesystem::path> writePlot(const std::filesystem::path& stem, const PlotSpec& spec);

// One style per series, shared by these charts and the window's speed-vs-error panel: the
// first 40 series all differ in colour or shape, and no two of the first eight share a
// shape with a similar colour (PCSS and "hierarchical 2L" were both orange diamonds).
enum class MarkerShape { Square, Diamond, Triangle, Circle, TriangleDown };
struct SeriesStyle {
  double r, g, b;  // 0..1, readable on white and on the window's dark plot
  MarkerShape shape;
};
SeriesStyle seriesStyle(int series);

// A method's name as a reader knows it ("Monte Carlo", "PCSS", "SSM", ...), from its stage.
std::string methodDisplayName(const std::string& method);
// A legend entry: the method's name, then the configuration when it says more
// ("Monte Carlo: hierarchical 2L", "PCSS").
std::string seriesLegend(const std::string& method, const std::string& family);
