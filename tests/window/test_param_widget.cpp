// The parameter widget (app/window/ui_widgets.h, drawParam) under `auto`, clicked as a user
// would (ImGui mouse events, no window or GL needed): the control shows what auto chose;
// unticking auto gives back the value set by hand, also for a choice the pipeline decides
// in place (Pipeline::decideAutoChoices writes its choice into the value).
#include <gtest/gtest.h>
#include <imgui.h>

#include <functional>

#include "window/ui_widgets.h"

namespace {

// One ImGui context with its font atlas built; frames drawn into one fixed window.
class ParamWidget : public ::testing::Test {
protected:
  void SetUp() override {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = {800, 600};
    io.DeltaTime = 1.0f / 60;
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  }
  void TearDown() override { ImGui::DestroyContext(); }

  // A frame with the mouse at `mouse`, the left button `down`; returns what drawParam said.
  bool frame(Param& param, std::optional<double> autoValue, ImVec2 mouse, bool down) {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = mouse;
    io.MouseDown[0] = down;
    ImGui::NewFrame();
    ImGui::SetNextWindowPos({0, 0});
    ImGui::SetNextWindowSize({800, 600});
    ImGui::Begin("params", nullptr, ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoMove);
    checkbox = ImGui::GetCursorScreenPos();  // the auto checkbox is the first item
    ImGui::PushItemWidth(300);
    const bool changed = drawParam(param, handValues, autoValue);
    ImGui::PopItemWidth();
    ImGui::End();
    ImGui::Render();
    return changed;
  }
  // Hover, press, release over the auto checkbox.
  bool clickAuto(Param& param, std::optional<double> autoValue) {
    const float h = ImGui::GetFrameHeight() * 0.5f;
    frame(param, autoValue, {checkbox.x + h, checkbox.y + h}, false);
    bool changed = frame(param, autoValue, {checkbox.x + h, checkbox.y + h}, true);
    changed |= frame(param, autoValue, {checkbox.x + h, checkbox.y + h}, false);
    return changed;
  }
  ImVec2 checkbox{8, 8};
  ParamHandValues handValues;  // the window keeps these in UiState::PanelMemory
};

}  // namespace

TEST_F(ParamWidget, AnIntegerUnderAutoShowsTheChoiceAndKeepsItsHandValue) {
  Param resolution = Param::integerOrAuto("resolution", "map size", 512, 128, 2048);
  frame(resolution, 256.0, {-1, -1}, false);  // lays the window out
  EXPECT_EQ(shownParamValue(resolution, 256.0), 256);  // auto chose 256: the slider shows it
  EXPECT_TRUE(clickAuto(resolution, 256.0));
  EXPECT_FALSE(resolution.automatic);
  EXPECT_EQ(resolution.asInt(), 512);  // the hand value is back
  EXPECT_EQ(shownParamValue(resolution, 256.0), 512);
  EXPECT_TRUE(clickAuto(resolution, 256.0));
  EXPECT_TRUE(resolution.automatic);
  EXPECT_EQ(shownParamValue(resolution, 256.0), 256);
}

TEST_F(ParamWidget, AChoiceDecidedInPlaceGetsItsHandValueBackWhenAutoIsUnticked) {
  Param hierarchy = Param::choice("hierarchy", "what the search reads", {"nbuffer", "minmax"}, 1);
  hierarchy.allowsAuto = true;  // set by hand to minmax
  frame(hierarchy, std::nullopt, {-1, -1}, false);
  EXPECT_TRUE(clickAuto(hierarchy, std::nullopt));  // auto ticked
  ASSERT_TRUE(hierarchy.automatic);
  hierarchy.value = 0;  // the pipeline's decision, written into the value
  EXPECT_EQ(shownParamValue(hierarchy, 0.0), 0);
  EXPECT_TRUE(clickAuto(hierarchy, 0.0));  // unticked
  EXPECT_FALSE(hierarchy.automatic);
  EXPECT_EQ(hierarchy.asEnum(), "minmax");
}
