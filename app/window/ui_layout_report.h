// What the last UI frame laid out, for scripts and tests (`print_layout`): one line per
// window drawn, with its rectangle and how far its contents reach, so a test can check that
// nothing floats over the views and that no panel's text runs past its right edge (the
// panels have no horizontal scrollbar: what does not fit is clipped).
#pragma once
#include <string>

//   layout LABEL: window NAME at X Y size W H contents CW CH overflow OX
// NAME: ImGui's window name (child windows: "Parent/Child_ID"); OX: pixels by which the
// contents reach past the window's inner right edge, in whole pixels (0 when they fit).
void printLayout(const std::string& label);
