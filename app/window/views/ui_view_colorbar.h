// The colour bar every single-channel view draws over the bottom of its image (the window's
// twin of the annotated export's band, app/figures/annotate.h): the colormap from the black
// to the white point, both values, and what they measure ("trace.cost: fetches"), with
// "auto range (p99)" while the range follows the data (ViewSettings::autoRange). Colour
// (RGB) views are their own key; categorical views get the inspector's legend instead.
#pragma once
#include <glm/glm.hpp>

#include <string>

class UiState;
class GlTexture;
struct ViewPanel;

// The bar's label: "trace.cost: fetches · auto range (p99)"; "" when the view draws none.
std::string colorBarLabel(const UiState& state, const ViewPanel& view, const GlTexture& texture);

// Before the view renders: an auto-ranged view takes its range from the data (once per run).
void updateAutoRange(const UiState& state, ViewPanel& view, const GlTexture& texture);

// After the image: the bar inside the image region (origin, size in screen pixels). Records
// its rectangle for the layout report (printColorBars).
void drawViewColorBar(const UiState& state, const ViewPanel& view, const GlTexture& texture,
                      glm::vec2 origin, glm::vec2 regionSize);

// For print_layout (app/window/ui_layout_report.h), one line per bar drawn last frame:
//   layout LABEL: colorbar VIEW at X Y size W H range LOW HIGH auto 0|1 label TEXT
void printColorBars(const std::string& label);
