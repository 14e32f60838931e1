// The report's scatter plot (`penumbra bench`: speed_vs_error.png): one marker per
// configuration, coloured by series, the Pareto frontier drawn as a line through its points
// (each labelled), axes with ticks, units and a legend; drawn with OpenImageIO's
// ImageBufAlgo (render_box, render_line, render_text or the bitmap font of plot_font.h).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

struct PlotPoint {
  double x = 0, y = 0;
  int series = 0;         // index into PlotSpec::seriesNames (colour and marker)
  std::string label;      // written next to frontier points
  bool frontier = false;  // on the Pareto frontier: ringed, joined, labelled
};

struct PlotSpec {
  std::string title, xLabel, yLabel;
  std::vector<std::string> seriesNames;
  std::vector<PlotPoint> points;
  std::string frontierCaption = "Pareto frontier (x, y):";
  bool logX = true;
  bool logY = false;
  bool connectSeries = false;  // a line through each series' points, in x order (sweeps)
  int width = 1000, height = 680;
  bool forceBitmapFont = false;  // tests
};

// Writes an 8-bit RGB PNG (atomically). Returns how text was drawn ("font DejaVuSans" or
// "built-in bitmap font") for the report. Throws std::runtime_error if it cannot write.
std::string writeScatterPlot(const std::filesystem::path& path, const PlotSpec& spec);

// Indices of the points no other point beats in both coordinates (minimising x and y).
std::vector<bool> paretoFrontier(const std::vector<double>& x, const std::vector<double>& y);
