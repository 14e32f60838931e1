// Text for the report's plots: OpenImageIO's render_text (FreeType) with DejaVu Sans when a
// font can be found, else a built-in 8x14 bitmap font (printable ASCII), so axis labels
// appear on any machine. Both draw into an OIIO ImageBuf.
#pragma once
#include <OpenImageIO/imagebuf.h>

#include <array>
#include <string>

enum class TextAlign { Left, Center, Right };

class PlotText {
public:
  // Probes for a usable font once; `forceBitmap` skips the probe (tests).
  explicit PlotText(bool forceBitmap = false);
  bool usesFont() const { return !fontName_.empty(); }
  const std::string& fontName() const { return fontName_; }  // "" when bitmap

  // Draws `text` with its baseline-ish top at y (top of the text box), aligned at x.
  // `size`: pixel height of the line (the bitmap font scales by whole multiples of 14).
  void draw(OIIO::ImageBuf& image, int x, int y, const std::string& text, int size,
            const std::array<float, 3>& color, TextAlign align = TextAlign::Left,
            bool vertical = false) const;
  int width(const std::string& text, int size) const;

private:
  std::string fontName_;
};
