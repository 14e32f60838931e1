#include "bench/pareto.h"

#include <cstddef>

std::vector<bool> paretoFrontier(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<bool> frontier(x.size(), true);
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = 0; j < x.size() && frontier[i]; ++j)
      if (j != i && x[j] <= x[i] && y[j] <= y[i] && (x[j] < x[i] || y[j] < y[i]))
        frontier[i] = false;
  return frontier;
}
