// The lesson panel (`penumbra lesson FILE`, docs/design.md#program): a lesson is a script
// (app/window/script/ui_script.h) whose "say" actions explain each step; this panel shows the
// lesson's title, the step number and the text in a strip below the views (the window's layout
// takes its height from theirs, so it never covers a view). Played interactively, it has the
// "Next" button (also Space or N) that lets the script go on to its next "say".
#pragma once

class UiState;

// The strip's height at the current UI scale: 0 until a script says something, then the
// step line with the button and kLessonTextLines lines for the title and the text (a longer
// text scrolls inside the strip). The same for every step, so the views keep their size.
inline constexpr int kLessonTextLines = 7;
float lessonPanelHeight(const UiState& state);

// Draws nothing until a script says something; else the strip at (x, y), width x height.
void drawLessonWindow(UiState& state, float x, float y, float width, float height);
