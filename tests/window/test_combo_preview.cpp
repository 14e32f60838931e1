// comboPreview (app/window/ui_widgets.h): a combo's preview of a long output name fits the
// combo and keeps the output's own name whole while it can. ImGui without a window: its
// default font (the one the window rebuilds at each UI scale) measures the text.
#include <gtest/gtest.h>
#include <imgui.h>

#include "window/ui_widgets.h"

namespace {

class ComboPreview : public ::testing::Test {
protected:
  void SetUp() override {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = {800, 600};
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);  // builds the default font
    ImGui::NewFrame();
  }
  void TearDown() override {
    ImGui::EndFrame();
    ImGui::DestroyContext();
  }
  // The text room of a combo `width` wide, as comboPreview counts it.
  static float room(float width) {
    return width - ImGui::GetFrameHeight() - 2 * ImGui::GetStyle().FramePadding.x;
  }
  static float textWidth(const std::string& text) { return ImGui::CalcTextSize(text.c_str()).x; }
};

TEST_F(ComboPreview, AWideComboShowsTheWholeName) {
  const std::string name = "hard_shadow.visibility";
  EXPECT_EQ(comboPreview(name, 400), name);
}

TEST_F(ComboPreview, ANarrowComboCutsTheStageAndKeepsTheOutput) {
  const std::string name = "hard_shadow.visibility";
  const float width = textWidth(name) + ImGui::GetFrameHeight();  // a little short of it
  const std::string preview = comboPreview(name, width);
  EXPECT_NE(preview, name);
  EXPECT_LE(textWidth(preview), room(width));
  EXPECT_EQ(preview.rfind("hard", 0), 0u) << preview;  // the stage's start
  EXPECT_EQ(preview.substr(preview.size() - 13), "...visibility") << preview;
  // The longest such cut: one more letter of the stage would not fit.
  const size_t kept = preview.size() - 13;
  EXPECT_GT(textWidth(name.substr(0, kept + 1) + "...visibility"), room(width)) << preview;
}

TEST_F(ComboPreview, WhenTheOutputAloneDoesNotFitTheEndIsCut) {
  const std::string name = "hard_shadow.visibility";
  const float width = textWidth("h...visib") + ImGui::GetFrameHeight() + 2 * ImGui::GetStyle().FramePadding.x;
  const std::string preview = comboPreview(name, width);
  EXPECT_LE(textWidth(preview), room(width)) << preview;
  EXPECT_EQ(preview.substr(preview.size() - 3), "...") << preview;
  EXPECT_EQ(preview.substr(0, preview.size() - 3), name.substr(0, preview.size() - 3)) << preview;
  EXPECT_GT(preview.size(), 4u) << preview;  // more than "h..."
}

}  // namespace
