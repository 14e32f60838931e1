#include "window/ui_log_panel.h"

#include <imgui.h>

#include <cstdio>

#include "window/ui_state.h"

namespace {

const ImVec4 kWarningColour{1.0f, 0.8f, 0.2f, 1.0f};
const ImVec4 kErrorColour{1.0f, 0.45f, 0.4f, 1.0f};

std::string countText(const UiLog& log) {
  std::string text;
  if (log.warnings() > 0)
    text += std::to_string(log.warnings()) + (log.warnings() == 1 ? " warning" : " warnings");
  if (log.errors() > 0)
    text += (text.empty() ? "" : ", ") + std::to_string(log.errors()) + (log.errors() == 1 ? " error" : " errors");
  return text;
}

}  // namespace

std::string elided(const std::string& text, float width) {
  if (ImGui::CalcTextSize(text.c_str()).x <= width) return text;
  const float dots = ImGui::CalcTextSize("...").x;
  if (width <= dots) return "";
  // The longest prefix that fits with the dots (text width grows with the prefix).
  size_t lo = 0, hi = text.size();
  while (lo < hi) {
    const size_t mid = (lo + hi + 1) / 2;
    if (ImGui::CalcTextSize(text.data(), text.data() + mid).x + dots <= width) lo = mid;
    else hi = mid - 1;
  }
  while (lo > 0 && (static_cast<unsigned char>(text[lo]) & 0xC0) == 0x80) --lo;  // UTF-8 boundary
  while (lo > 0 && text[lo - 1] == ' ') --lo;
  return text.substr(0, lo) + "...";
}

void drawLogCount(UiState& state) {
  const UiLog& log = state.log;
  if (log.warnings() + log.errors() == 0) return;
  const std::string text = countText(log) + (log.unread() > 0 && !state.showLog ? " (new)" : "");
  ImGui::PushStyleColor(ImGuiCol_Text, log.errors() > 0 ? kErrorColour : kWarningColour);
  if (ImGui::SmallButton((text + "##log_count").c_str())) state.showLog = !state.showLog;
  ImGui::PopStyleColor();
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("The session's log: every warning and error, whole, with its time and source.\n"
                      "Click to %s it.", state.showLog ? "close" : "open");
  ImGui::SameLine();
}

void drawLogWindow(UiState& state) {
  if (!state.showLog) return;
  UiLog& log = state.log;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos({display.x * 0.5f, display.y * 0.45f}, ImGuiCond_Appearing, {0.5f, 0.0f});
  ImGui::SetNextWindowSize({display.x * 0.6f, display.y * 0.45f}, ImGuiCond_Appearing);
  if (ImGui::Begin("Log", &state.showLog)) {
    const std::string count = countText(log);
    ImGui::TextUnformatted(count.empty() ? "Nothing logged." : count.c_str());
    ImGui::SameLine();
    if (ImGui::SmallButton("Copy all")) ImGui::SetClipboardText(log.text().c_str());
    ImGui::SameLine();
    if (ImGui::SmallButton("Clear")) log.clear();
    if (log.dropped() > 0) {
      ImGui::SameLine();
      ImGui::TextDisabled("(%zu oldest let go)", log.dropped());
    }
    ImGui::Separator();
    ImGui::BeginChild("##log_entries");
    const bool atBottom = ImGui::GetScrollY() >= ImGui::GetScrollMaxY() - 1;
    for (const LogEntry& entry : log.entries()) {
      ImGui::TextDisabled("%s", entry.clock.c_str());
      ImGui::SameLine();
      ImGui::TextColored(entry.level == LogLevel::Warning ? kWarningColour : kErrorColour, "%s",
                         entry.level == LogLevel::Warning ? "warning" : "error");
      ImGui::SameLine();
      std::string text = entry.source + ": " + entry.message;
      if (entry.repeats > 1) text += " (x" + std::to_string(entry.repeats) + ")";
      ImGui::TextWrapped("%s", text.c_str());
    }
    if (atBottom && log.unread() > 0) ImGui::SetScrollHereY(1.0f);  // follow new entries
    ImGui::EndChild();
    log.markRead();
  }
  ImGui::End();
}

void printLog(const UiState& state, const std::string& label) {
  const UiLog& log = state.log;
  std::printf("log %s: %d warnings, %d errors\n", label.c_str(), log.warnings(), log.errors());
  for (const LogEntry& entry : log.entries()) std::printf("log %s: %s\n", label.c_str(), UiLog::line(entry).c_str());
  std::fflush(stdout);
}
