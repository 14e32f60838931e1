// Whether a UI frame shows anything new. The window draws the frame (GL) and swaps only then:
// on llvmpipe, drawing ImGui's frame at 1280x800 is most of what a UI frame costs (building
// it is a few per cent of that), so a window that woke with nothing changed draws nothing.
// New means: other draw data (vertices, clip rectangles, textures), another size, or other
// contents of the textures the views show (the draw data names a texture, not what it holds:
// the views add that as `content`, app/window/ui_state.h shownContent).
#pragma once
#include <cstdint>

struct ImDrawData;

class FrameChange {
public:
  // True when this frame differs from the last one that was presented (or nothing was yet,
  // or forceNext was called); it is then the one remembered.
  bool changed(const ImDrawData& data, std::uint64_t content);
  void forceNext() { force_ = true; }  // the window was exposed or resized: draw again

private:
  std::uint64_t last_ = 0;
  bool force_ = true;
};

// Mixes `value` into `hash` (the views' content keys).
void mixHash(std::uint64_t& hash, std::uint64_t value);
