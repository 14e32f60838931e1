// A UI frame that an exception leaves midway (inside a window, a child, an open popup and a
// tab bar, with a colour, a style, an ID, a disabled block and a group pushed) is closed by
// closeInterruptedFrame (app/window/ui_frame_recover.h): every ImGui stack is back to empty
// and the next frames run and render normally. Debian's ImGui is built with its assertions
// on, so an unbalanced stack in the frames after would also abort the test.
#include <gtest/gtest.h>

#include <imgui.h>
#include <imgui_internal.h>

#include <stdexcept>

#include "window/ui_frame_recover.h"

namespace {

struct ImGuiContextScope {
  ImGuiContextScope() {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = {640, 480};
    io.DeltaTime = 1.0f / 60;
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);  // a built atlas, as a backend gives
  }
  ~ImGuiContextScope() { ImGui::DestroyContext(); }
};

// The window's shapes: a panel, a view child, a combo-like popup and a tab bar. `fail`
// throws inside the popup, as a selection that reads an output not written this run did.
void frame(bool fail) {
  ImGui::NewFrame();
  ImGui::Begin("panel");
  ImGui::BeginChild("view", {300, 200}, true);
  ImGui::PushStyleColor(ImGuiCol_Border, IM_COL32(230, 180, 60, 255));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, {4, 4});
  ImGui::PushID("toolbar");
  ImGui::BeginGroup();
  ImGui::BeginDisabled(false);
  if (ImGui::BeginTabBar("tabs")) {
    if (ImGui::BeginTabItem("Inspector")) {
      ImGui::OpenPopup("outputs");
      if (ImGui::BeginPopup("outputs")) {
        ImGui::Selectable("composite.color");
        if (fail) throw std::runtime_error("output 'composite.color' has not been written this run");
        ImGui::EndPopup();
      }
      ImGui::EndTabItem();
    }
    ImGui::EndTabBar();
  }
  ImGui::EndDisabled();
  ImGui::EndGroup();
  ImGui::PopID();
  ImGui::PopStyleVar();
  ImGui::PopStyleColor();
  ImGui::EndChild();
  ImGui::End();
  ImGui::Render();
}

}  // namespace

TEST(WindowRecover, AFrameLeftMidwayIsClosedAndTheNextFramesRun) {
  ImGuiContextScope scope;
  ImGuiContext& g = *ImGui::GetCurrentContext();
  frame(false);
  EXPECT_FALSE(closeInterruptedFrame()) << "no frame is open between frames";

  std::string recovered;
  try {
    frame(true);
    FAIL() << "the frame did not throw";
  } catch (const std::runtime_error&) {
    EXPECT_GT(g.CurrentWindowStack.Size, 2) << "the throw left windows open";
    EXPECT_TRUE(closeInterruptedFrame(&recovered));
  }
  EXPECT_NE(recovered.find("view"), std::string::npos) << recovered;  // the child, named
  EXPECT_FALSE(g.WithinFrameScope);
  EXPECT_EQ(g.CurrentWindowStack.Size, 0);
  EXPECT_EQ(g.ColorStack.Size, 0);
  EXPECT_EQ(g.StyleVarStack.Size, 0);
  EXPECT_EQ(g.GroupStack.Size, 0);
  EXPECT_EQ(g.BeginPopupStack.Size, 0);
  EXPECT_EQ(g.DisabledStackSize, 0);
  EXPECT_EQ(g.CurrentTabBar, nullptr);
  ASSERT_NE(ImGui::GetDrawData(), nullptr);
  EXPECT_TRUE(ImGui::GetDrawData()->Valid) << "the frame is rendered as far as it was drawn";

  for (int i = 0; i < 3; ++i) frame(false);  // and the window goes on
  EXPECT_TRUE(ImGui::GetDrawData()->Valid);
  EXPECT_EQ(g.CurrentWindowStack.Size, 0);
}
