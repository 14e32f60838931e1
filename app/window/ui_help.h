// The help window (F1 or '?'): keyboard shortcuts and mouse controls; and the shader log
// window that opens when a hot reload fails.
#pragma once

class UiState;

struct Shortcut {
  const char* keys;
  const char* action;
};
// The list the help window shows (window_app.cpp implements each).
const Shortcut* shortcuts(int& count);

void drawHelpWindow(UiState& state);
void drawShaderLogWindow(UiState& state);
