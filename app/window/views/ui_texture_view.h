// One texture view in the centre area: toolbar, the image with zoom / pan / texel grid /
// pick marker / overlay rectangles, the hover readout, and the mouse: wheel zooms, left drag
// pans the image, left click picks, right drag orbits the camera, middle (or Shift+right)
// drag pans it, Ctrl+wheel dollies it.
#pragma once
#include <imgui.h>

class UiState;

// Draws view `index` into a child region of `size`; returns true while the mouse moves the
// camera (the window may render a cheaper preview meanwhile).
bool drawTextureView(UiState& state, int index, ImVec2 size);
