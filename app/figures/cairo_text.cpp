#include "figures/cairo_text.h"

#include <sstream>

namespace {

const char* kFont = "DejaVu Sans";

void setFont(cairo_t* cr, double size, bool bold) {
  cairo_select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
}

// Removes the last UTF-8 character whole (cairo refuses a string cut inside one).
void popCharacter(std::string& text) {
  while (!text.empty() && (static_cast<unsigned char>(text.back()) & 0xC0) == 0x80) text.pop_back();
  if (!text.empty()) text.pop_back();
}

}  // namespace

double textWidth(cairo_t* cr, const std::string& text, double size, bool bold) {
  setFont(cr, size, bold);
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  return extents.x_advance;
}

std::vector<std::string> wrapText(cairo_t* cr, const std::string& text, double size, double width,
                                  int maxLines) {
  std::vector<std::string> lines;
  std::istringstream words(text);
  std::string word, line;
  while (words >> word) {
    const std::string longer = line.empty() ? word : line + " " + word;
    if (line.empty() || textWidth(cr, longer, size) <= width) {
      line = longer;
      continue;
    }
    lines.push_back(line);
    line = word;
  }
  if (!line.empty()) lines.push_back(line);
  if (int(lines.size()) > maxLines) {  // cut: the last kept line ends with an ellipsis
    lines.resize(size_t(maxLines));
    std::string& last = lines.back();
    while (!last.empty() && textWidth(cr, last + "…", size) > width) popCharacter(last);
    last += "…";
  }
  return lines;
}

void drawText(cairo_t* cr, double x, double y, const std::string& text, double size, double gray,
              bool bold) {
  cairo_save(cr);
  setFont(cr, size, bold);
  cairo_font_extents_t font;
  cairo_font_extents(cr, &font);
  cairo_set_source_rgb(cr, gray, gray, gray);
  cairo_move_to(cr, x, y + font.ascent);
  cairo_show_text(cr, text.c_str());
  cairo_restore(cr);
}
