#include "window/ui_scale.h"

#include <imgui.h>
#include <backends/imgui_impl_opengl3.h>

#include <cmath>

bool validUiScale(float scale) {
  return std::isfinite(scale) && scale >= kMinUiScale && scale <= kMaxUiScale;
}

void applyUiScale(float scale, float& applied) {
  if (!validUiScale(scale) || scale == applied) return;
  applied = scale;
  // 1. The font: ImGui's own (ProggyClean), rasterised at the scaled size.
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->Clear();
  ImFontConfig font;
  font.SizePixels = std::round(13.0f * scale);
  io.Fonts->AddFontDefault(&font);
  ImGui_ImplOpenGL3_DestroyFontsTexture();
  ImGui_ImplOpenGL3_CreateFontsTexture();
  // 2. Paddings, spacings, rounding, scrollbars: from the defaults, so scales do not compound.
  ImGuiStyle style;
  ImGui::StyleColorsDark(&style);
  style.ScaleAllSizes(scale);
  ImGui::GetStyle() = style;
}
