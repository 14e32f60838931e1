// The window's status line (window_app.cpp draws it under the panels): the log's count, what
// happened last (scene warnings first) and, on the right, the eye size, the pipeline's
// median time and runs per second, the UI's frames per second and whether it previews.
#pragma once

class UiState;
struct Layout;

void drawStatusLine(UiState& state, const Layout& layout);
