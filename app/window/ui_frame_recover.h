// A UI frame that an exception left midway (a stage, a panel or an action threw between
// ImGui::NewFrame and ImGui::Render), closed as ImGui expects, so the next frame starts clean:
// every window and child begun is ended, every pushed colour, style, ID, disabled block,
// group, tab bar and table popped (ImGui::ErrorCheckEndFrameRecover, imgui_internal.h), then
// the frame is rendered as far as it was drawn. The window's frame loop calls it from its
// one catch (window_app.cpp); what was recovered goes to `recovered`, one line each.
#pragma once
#include <string>

// Returns false when no frame was open (the exception came before NewFrame or after Render).
bool closeInterruptedFrame(std::string* recovered = nullptr);
