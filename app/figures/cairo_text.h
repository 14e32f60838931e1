// Text for the figure files (annotate.cpp, figure_sheet.cpp): one font, words wrapped to a
// width, lines cut with an ellipsis when they do not fit.
#pragma once
#include <cairo.h>

#include <string>
#include <vector>

// Splits `text` into at most `maxLines` lines no wider than `width` at `size` points.
std::vector<std::string> wrapText(cairo_t* cr, const std::string& text, double size, double width,
                                  int maxLines);
// Draws one line with its top edge at y; `gray` in [0, 1].
void drawText(cairo_t* cr, double x, double y, const std::string& text, double size, double gray,
              bool bold = false);
double textWidth(cairo_t* cr, const std::string& text, double size, bool bold = false);
