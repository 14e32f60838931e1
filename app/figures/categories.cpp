#include "figures/categories.h"

#include <cmath>
#include <cstdio>
#include <regex>

#include "io/colormap.h"

// 1. "<integer> <word>" pairs of the doc.
std::map<int, std::string> categoryNamesFromDoc(const std::string& doc) {
  std::map<int, std::string> names;
  static const std::regex pair(R"((?:^|[\s:,(])(\d+)\s+([A-Za-z_]+))");
  for (auto it = std::sregex_iterator(doc.begin(), doc.end(), pair); it != std::sregex_iterator(); ++it)
    names.emplace(std::stoi((*it)[1].str()), (*it)[2].str());
  return names;
}

// 2. Rounded like app/io/colormap.cpp's categorical map (lround of |value|); NaN skipped.
std::map<int, long> categoryCounts(const std::vector<float>& values, int channelCount, int channel) {
  std::map<int, long> counts;
  for (size_t i = size_t(channel); i < values.size(); i += size_t(channelCount))
    if (std::isfinite(values[i])) ++counts[int(std::lround(std::fabs(values[i])))];
  return counts;
}

// 3. Swatch and "value name share" per category present.
std::vector<LegendEntry> categoryLegend(const std::vector<float>& values, int channelCount,
                                        int channel, const std::string& doc) {
  const auto names = categoryNamesFromDoc(doc);
  const double total = double(values.size() / size_t(channelCount > 0 ? channelCount : 1));
  std::vector<LegendEntry> legend;
  for (const auto& [value, count] : categoryCounts(values, channelCount, channel)) {
    const auto name = names.find(value);
    char text[96];
    std::snprintf(text, sizeof text, "%d %s %.1f%%", value,
                  name != names.end() ? name->second.c_str() : "", 100.0 * double(count) / total);
    legend.push_back({applyColormap(Colormap::Categorical, 0, float(value)), text});
  }
  return legend;
}
