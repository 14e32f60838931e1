// The Pareto frontier of (time, error) points, for the bench report, its plots and the
// window's speed-against-error panel: the one definition.
#pragma once
#include <cstddef>
#include <vector>

// frontier[i]: no other point is at least as good in both coordinates and better in one
// (minimising x and y). Equal points are all on the frontier.
std::vector<bool> paretoFrontier(const std::vector<double>& x, const std::vector<double>& y);
