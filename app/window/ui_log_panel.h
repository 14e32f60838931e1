// The log panel and the status line's log count (the ImGui side of ui_log.h).
#pragma once
#include <string>

class UiState;

// A floating window with every entry of the session's log (state.showLog), newest at the
// bottom, each whole (wrapped), with its time, level and source; Copy all and Clear.
void drawLogWindow(UiState& state);

// The status line's count, "2 warnings, 1 error" (coloured, nothing when the log is empty):
// a click opens or closes the log panel.
void drawLogCount(UiState& state);

// `text` cut with "..." so that it is at most `width` pixels wide in the current font.
std::string elided(const std::string& text, float width);

// Script "print_log": "log LABEL: W warnings, E errors" then one "log LABEL: <line>" per entry.
void printLog(const UiState& state, const std::string& label);
