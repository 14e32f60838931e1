// A legend for views shown through the categorical colormap (masks such as classify.mask):
// each value's colour swatch, its name, pixel count and percentage. Names are read from the
// output's doc ("0 background, 1 lit, 2 penumbra, ..."), so stages declare them once.
#pragma once
#include <map>
#include <string>
#include <vector>

class UiState;
struct ViewPanel;

// "0 background, 1 lit" -> {0: "background", 1: "lit"}.
std::map<int, std::string> categoryNamesFromDoc(const std::string& doc);
// Value -> count over all texels of the shown channel (values rounded as the colormap does).
std::map<int, long> categoryCounts(const std::vector<float>& values, int channelCount, int channel);

// Draws the legend for `view` if it shows one channel through the categorical colormap.
void drawCategoryLegend(const UiState& state, const ViewPanel& view);
