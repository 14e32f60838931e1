// The lesson panel (`penumbra lesson FILE`, docs/design.md#program): a lesson is a script
// (app/window/script/ui_script.h) whose "say" actions explain each step; this panel shows the
// lesson's title, the step number and the text over the bottom of the views. Played interactively,
// it has the "Next" button (also Space or N) that lets the script go on to its next "say".
#pragma once

class UiState;

// Draws nothing until a script says something. `centreX`, `width`, `bottom`: the views' area.
void drawLessonWindow(UiState& state, float centreX, float width, float bottom);
