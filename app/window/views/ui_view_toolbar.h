// The controls above a texture view (RenderDoc's texture viewer): output and lock, channel
// toggles, colormap, array level, black/white point with autofit and reset, overlay, zoom,
// and the view's exports.
#pragma once

class UiState;
struct ViewPanel;
class GlTexture;

// `texture` is the output's texture this frame, or nullptr if it was not written. `compact`
// (the 2x2 grid): the output and a "..." button that opens the rest (view.toolsOpen).
void drawViewToolbar(UiState& state, ViewPanel& view, const GlTexture* texture, bool compact);

// Fits black/white to the finite values of the shown channels in the visible texels.
void autofitView(ViewPanel& view, const GlTexture& texture);
// Back to the output's declared display (keeps the level).
void resetView(UiState& state, ViewPanel& view, const GlTexture& texture);
