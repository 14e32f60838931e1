// A legend for views shown through the categorical colormap (masks such as classify.mask):
// each value's colour swatch, its name, pixel count and percentage. Names are read from the
// output's doc ("0 background, 1 lit, 2 penumbra, ..."), so stages declare them once.
#pragma once
#include <map>
#include <string>

#include "figures/categories.h"

class UiState;
struct ViewPanel;

// What a view's legend keeps between frames (ViewPanel::categories): the counts per
// category, counted once per pipeline run and view content (`key`).
struct CategoryCounts {
  std::map<int, long> counts;
  std::string key;
};

// Draws the legend for `view` if it shows one channel through the categorical colormap.
void drawCategoryLegend(const UiState& state, const ViewPanel& view);
