// The value below which `fraction` of the total weight lies (values weighted by, e.g., the
// screen area of each probe): how `auto` reads "98% of the penumbra area" from its probes
// (shared_inputs/light/auto_settings.cpp for the map, soft_shadow_maps/ssm/auto_ssm.cpp for SSM).
#pragma once
#include <algorithm>
#include <utility>
#include <vector>

inline double weightedPercentile(const std::vector<double>& values, const std::vector<double>& weights,
                                 double fraction) {
  std::vector<std::pair<double, double>> sorted;
  double total = 0;
  for (size_t i = 0; i < values.size() && i < weights.size(); ++i) {
    sorted.emplace_back(values[i], weights[i]);
    total += weights[i];
  }
  std::sort(sorted.begin(), sorted.end());
  double below = 0;
  for (const auto& [value, weight] : sorted)
    if ((below += weight) >= fraction * total) return value;
  return sorted.empty() ? 0 : sorted.back().first;
}
