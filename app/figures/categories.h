// Categories of a mask (classify.mask): their names, declared once in the output's doc
// ("0 background, 1 lit, 2 penumbra, ..."), and how many texels each holds. Shared by the
// window's legend (app/window/views/ui_categories.h) and annotated PNGs (annotate.h).
#pragma once
#include <map>
#include <string>
#include <vector>

#include "figures/annotate.h"

// "0 background, 1 lit" -> {0: "background", 1: "lit"}.
std::map<int, std::string> categoryNamesFromDoc(const std::string& doc);
// Value -> count over all texels of the shown channel (values rounded as the colormap does).
std::map<int, long> categoryCounts(const std::vector<float>& values, int channelCount, int channel);
// The legend entries ("2 penumbra 12.3%" with the categorical colour) of one channel.
std::vector<LegendEntry> categoryLegend(const std::vector<float>& values, int channelCount,
                                        int channel, const std::string& doc);
