// The colour bar every single-channel view draws over the bottom of its image (the window's
// twin of the annotated export's band, app/figures/annotate.h): the colormap from the black
// to the white point, both values, and what they measure ("trace.cost: fetches"), with
// "auto range (p99)" while the range follows the data (ViewSettings::autoRange). Colour
// (RGB) views are their own key; categorical views get the inspector's legend instead.
#pragma once
#include <glm/glm.hpp>

#include <string>
#include <vector>

class UiState;
class GlTexture;
struct ViewPanel;

// The bars drawn in one UI frame (UiState::panelMemory), for printColorBars.
struct DrawnColorBar {
  int view = 0;
  glm::vec2 min{0}, size{0};  // screen pixels
  float low = 0, high = 1;
  bool automatic = false;
  std::string label;
};
struct DrawnColorBars {
  std::vector<DrawnColorBar> bars;
  int frame = -1;  // the ImGui frame count they were drawn in
};

// The bar's label: "trace.cost: fetches · auto range (p99)"; "" when the view draws none.
std::string colorBarLabel(const UiState& state, const ViewPanel& view, const GlTexture& texture);

// Before the view renders: an auto-ranged view takes its range from the data (once per run).
void updateAutoRange(const UiState& state, ViewPanel& view, const GlTexture& texture);

// After the image: the bar inside the image region (origin, size in screen pixels). Records
// its rectangle in state.panelMemory.colorBars for the layout report (printColorBars).
void drawViewColorBar(UiState& state, const ViewPanel& view, const GlTexture& texture,
                      glm::vec2 origin, glm::vec2 regionSize);

// For print_layout (app/window/ui_layout_report.h), one line per bar drawn last frame:
//   layout LABEL: colorbar VIEW at X Y size W H range LOW HIGH auto 0|1 label TEXT
void printColorBars(const UiState& state, const std::string& label);
