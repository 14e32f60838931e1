// A lesson's figure sheet (docs/lessons.md): its exported panels side by side, like the papers'
// figures, each under a label "(a)", "(b)", ... and its caption, with the lesson's title on
// top; written as PNG and PDF (cairo). The layout depends only on the panel count, so a
// sheet's size says how many panels it holds (figureSheetSize).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

struct FigurePanel {
  std::filesystem::path png;
  std::string caption;
  // Only this rectangle of the PNG (pixels, row 0 at the top) goes on the sheet, so that a
  // window screenshot shows the widget it means at a readable size; empty: the whole image.
  struct Rect {
    int x = 0, y = 0, width = 0, height = 0;
  } crop{};
};

// Every panel fills a kSheetCell x (kSheetImage + kSheetCaption) cell (the image scaled to
// fit kSheetCell x kSheetImage), at most kSheetColumns per row.
constexpr int kSheetCell = 400, kSheetImage = 300, kSheetCaption = 58, kSheetColumns = 3;
constexpr int kSheetMargin = 16, kSheetGap = 12, kSheetTitle = 34;

struct SheetSize {
  int width = 0, height = 0;
};
SheetSize figureSheetSize(int panelCount);

// Writes `stem`.png and `stem`.pdf; returns their paths. Throws std::runtime_error naming
// a panel it cannot read or a file it cannot write.
std::vector<std::filesystem::path> writeFigureSheet(const std::filesystem::path& stem,
                                                    const std::string& title,
                                                    const std::vector<FigurePanel>& panels);
