// What the last UI frame laid out, for scripts and tests (`print_layout`): one line per
// window drawn, with its rectangle and how far its contents reach; one line per run of text
// the font drew, with its extent and the clip rectangle it was drawn in; one line per image.
// So a test can check that nothing floats over the views, that no text is cut by its frame
// or drawn over other text, and how large the views' images are.
//
// Text and images are read back from ImGui's draw data (every glyph quad the font emitted,
// whatever widget drew it), not from the calls that asked for them, so nothing escapes the
// report by being drawn through another path. A glyph is known by its place in the font
// atlas; its whole box follows from how much of that place the quad kept, so a glyph that
// was trimmed to a frame (ImGui clips frame text on the CPU) or reaches past the scissor
// rectangle counts as cut. What the report cannot see: a glyph the font skipped entirely
// because it lay wholly outside the clip rectangle (a line cut exactly between two glyphs
// shows no trimmed glyph); the window line's `overflow` covers laid-out text past a
// window's right edge.
#pragma once
#include <string>
#include <vector>

class UiState;

struct ImDrawData;

struct LayoutRect {
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool intersects(const LayoutRect& o, float margin = 0.5f) const {
    return x0 + margin < o.x1 && o.x0 + margin < x1 && y0 + margin < o.y1 && o.y0 + margin < y1;
  }
};

// One run of text: consecutive glyphs of one line drawn by one call (words kept together
// across spaces).
struct LayoutText {
  std::string window;  // the ImGui window whose draw list holds it
  std::string text;    // the glyphs' characters (UTF-8), spaces restored from the pen gaps
  LayoutRect extent;   // pen start to pen end, line top to line top + font size
  LayoutRect ink;      // the union of the glyphs' whole boxes (what would show unclipped)
  LayoutRect clip;     // the draw command's clip (scissor) rectangle
  // The frame it is drawn on: the last filled rectangle of its window drawn before it that
  // holds its visible glyphs (a button, a field, a header, a table row, at least the
  // window's background; slider grabs do not count). Text that does not fit a frame is
  // trimmed to it, and glyphs wholly past the frame are not drawn at all: a run whose pen
  // box reaches past its frame lost glyphs even when no trimmed glyph shows it.
  LayoutRect frame;
  bool hasFrame = false;
  size_t framesBefore = 0;  // (while measuring: filled rectangles drawn before it)
  float cutX = 0, cutY = 0;  // pixels of glyph boxes cut off left/right, top/bottom
  // Its window scrolls (vertically, horizontally): text cut at a scrolling edge is fine.
  bool windowScrolls = false, windowScrollsX = false;
  bool ellipsis = false;       // ImGui shortened it to fit and drew "..." after it (tabs)
};

// One textured quad other than the font's (a view's image, a colour bar).
struct LayoutImage {
  std::string window;
  LayoutRect rect, clip;
};

struct LayoutFrame {
  std::vector<LayoutText> texts;
  std::vector<LayoutImage> images;
};

// The text and images of `data` (ImGui::GetDrawData() after ImGui::Render(), before the
// next ImGui::NewFrame()).
LayoutFrame measureLayout(const ImDrawData& data);

//   layout LABEL: window NAME at X Y size W H contents CW CH overflow OX
//   layout LABEL: text NAME at X Y size W H clip X0 Y0 X1 Y1 ink X0 Y0 X1 Y1 frame X0 Y0 X1 Y1 cut CX CY scrolls SX SY ellipsis E "TEXT"
//   layout LABEL: image NAME at X Y size W H clip X0 Y0 X1 Y1
// NAME: ImGui's window name (child windows: "Parent/Child_ID"); OX: pixels by which the
// contents reach past the window's inner right edge, in whole pixels (0 when they fit).
// Text: its extent (pen box), the clip rectangle, the part of its glyphs that shows (ink), cut CX CY: pixels of its glyphs cut off horizontally and
// vertically (0.5 px tolerance: ImGui's pixel snapping), SX SY: 1 when its window scrolls horizontally, vertically; E: 1
// when ImGui cut it short with its own ellipsis (three dots drawn closer than the font's
// advance; a "..." inside the text, as comboPreview() writes it, is the text's own).
void printLayout(const UiState& state, const std::string& label);
