// Figures for a report (docs/lessons.md): every lesson in lessons/ parses and is a lesson (a title,
// texts, at least one panel); the figure sheet's size follows from its panel count alone;
// an annotated PNG carries the view's colour bar (checked against the colormap itself), a
// categorical legend, and `penumbra export --annotate` annotates PNGs while the EXRs stay raw.
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "figures/annotate.h"
#include "figures/categories.h"
#include "figures/figure_sheet.h"
#include "io/colormap.h"
#include "io/image_export.h"
#include "support/command.h"
#include "support/window_test.h"
#include "window/script/ui_script.h"

namespace fs = std::filesystem;

namespace {

OIIO::ImageSpec specOf(const fs::path& png) {
  OIIO::ImageBuf image(png.string());
  EXPECT_TRUE(image.read()) << png << ": " << image.geterror();
  return image.spec();
}

}  // namespace

TEST(LessonFigures, EveryLessonParsesAndHasATitleTextsAndPanels) {
  int lessons = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(PENUMBRA_SOURCE_DIR) / "lessons")) {
    if (entry.path().extension() != ".json") continue;
    ++lessons;
    std::vector<ScriptAction> actions;
    ASSERT_EQ(parseScriptFile(entry.path().string(), actions), "") << entry.path();
    int titles = 0, says = 0, panels = 0;
    for (const ScriptAction& action : actions) {
      titles += action.name == "lesson";
      says += action.name == "say";
      panels += action.name == "export_view" || action.name == "screenshot";
      EXPECT_NE(action.name, "export_dir") << entry.path() << ": the default folder is the lesson's name";
    }
    EXPECT_EQ(titles, 1) << entry.path();
    EXPECT_GE(says, 2) << entry.path();
    EXPECT_GE(panels, 1) << entry.path();
    EXPECT_LE(panels, 26) << entry.path() << ": a sheet labels panels (a) to (z)";
  }
  EXPECT_GE(lessons, 11);  // Figs 3.2, 3.3, 3.4-3.5, 3.6-3.7, 3.8, 3.9, 4.1, 4.2, Alg. 1, §3.1, all methods
}

TEST(LessonFigures, ASheetsSizeFollowsItsPanelCount) {
  const fs::path dir = scratchDirectory("figure_sheet");
  // Panels of two shapes: a 4:3 view and a wide window screenshot.
  writePng(dir / "view.png", std::vector<std::uint8_t>(64 * 48 * 3, 200), 64, 48);
  writePng(dir / "wide.png", std::vector<std::uint8_t>(160 * 50 * 3, 90), 160, 50);
  for (int count : {1, 2, 3, 4, 7}) {
    std::vector<FigurePanel> panels;
    for (int i = 0; i < count; ++i)
      panels.push_back({dir / (i % 2 ? "wide.png" : "view.png"), "panel " + std::to_string(i)});
    const auto written = writeFigureSheet(dir / ("sheet" + std::to_string(count)), "Title", panels);
    ASSERT_EQ(written.size(), 2u);
    const int columns = std::min(count, 3), rows = (count + 2) / 3;
    const OIIO::ImageSpec spec = specOf(written[0]);
    EXPECT_EQ(spec.width, 2 * 16 + columns * 400 + (columns - 1) * 12) << count;
    EXPECT_EQ(spec.height, 2 * 16 + 34 + rows * (300 + 58) + (rows - 1) * 12) << count;
    EXPECT_GT(fs::file_size(written[1]), 1000u) << count;
  }
  EXPECT_THROW(writeFigureSheet(dir / "none", "Title", {}), std::runtime_error);
  EXPECT_THROW(writeFigureSheet(dir / "missing", "Title", {{dir / "nope.png", "x"}}),
               std::runtime_error);
  fs::remove_all(dir);
}

TEST(LessonFigures, AnAnnotatedImageCarriesTheColormapsBarBelowTheImageUntouched) {
  const int width = 200, height = 40;
  std::vector<std::uint8_t> rgb(size_t(width) * height * 3, 77);
  Annotation annotation;
  annotation.bar = ColorBar{Colormap::Perceptual, 0, 2, "trace.cost: fetches"};
  annotation.caption = "cube · trace.cost · 200x40";
  const int band = annotationHeight(annotation, width);
  ASSERT_GT(band, 20);
  const auto out = annotateImage(rgb, width, height, annotation);
  ASSERT_EQ(out.size(), size_t(width) * (height + band) * 3);
  EXPECT_TRUE(std::equal(rgb.begin(), rgb.end(), out.begin())) << "the image itself changed";
  // The bar's first row (just under the image and its padding): left end = the colormap at 0,
  // right end = at 1, as app/io/colormap.cpp maps them.
  const int row = height + 6 + 6;
  const auto at = [&](int x) {
    const std::uint8_t* p = &out[(size_t(row) * width + x) * 3];
    return std::array<int, 3>{p[0], p[1], p[2]};
  };
  const auto low = applyColormap(Colormap::Perceptual, 0, 0), high = applyColormap(Colormap::Perceptual, 1, 2);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(at(8)[size_t(c)], low[size_t(c)], 12) << c;
    EXPECT_NEAR(at(width - 9)[size_t(c)], high[size_t(c)], 12) << c;
  }
  // Nothing to say: no band.
  EXPECT_EQ(annotationHeight(Annotation{}, width), 0);
}

// A 192-pixel-wide export (the Atty bench's error views): the bar's label would run into
// the high end's value, so it gets its own line, drawn (dark text pixels there); the caption
// gets four lines instead of two.
TEST(LessonFigures, OnANarrowImageTheBarsLabelGetsItsOwnLine) {
  Annotation annotation;
  annotation.bar = ColorBar{Colormap::Diverging, -1, 1, "error.signed"};
  annotation.caption = "bunny-atty · error.signed · 192x192 · ssm.passes=one · light.resolution=128";
  const int wide = annotationHeight(annotation, 800), narrow = annotationHeight(annotation, 192);
  EXPECT_EQ(narrow, wide + 16 + 2 * 16);  // the label's line, two more caption lines
  const int width = 192, height = 20;
  const auto out = annotateImage(std::vector<std::uint8_t>(size_t(width) * height * 3, 255), width,
                                 height, annotation);
  const int labelRow = height + 6 + 12 + 2 + 16 + 2;  // pad, bar, ticks
  int dark = 0;
  for (int y = labelRow; y < labelRow + 16; ++y)
    for (int x = 0; x < width; ++x) dark += out[(size_t(y) * width + x) * 3] < 128;
  EXPECT_GT(dark, 20) << "no label drawn on its own line";
}

TEST(LessonFigures, ACategoricalLegendNamesEachClassFromTheDocWithItsShare) {
  const std::vector<float> mask = {1, 1, 2, 3, 1, 2, 2, 2};  // 3 lit, 4 penumbra, 1 umbra
  const auto legend = categoryLegend(mask, 1, 0, "Class per pixel: 0 background, 1 lit, 2 penumbra, 3 umbra.");
  ASSERT_EQ(legend.size(), 3u);
  EXPECT_EQ(legend[0].text, "1 lit 37.5%");
  EXPECT_EQ(legend[1].text, "2 penumbra 50.0%");
  EXPECT_EQ(legend[2].text, "3 umbra 12.5%");
  EXPECT_EQ(legend[1].rgb, applyColormap(Colormap::Categorical, 0, 2));
}

TEST(LessonFigures, ExportAnnotateAnnotatesPngsOnlyWhenAskedAndLeavesExrsRaw) {
  const fs::path dir = scratchDirectory("export_annotate");
  for (const bool annotate : {false, true}) {
    const fs::path out = dir / (annotate ? "annotated" : "plain");
    const auto result = runPenumbra("export --width 96 --height 72 --set trace.rays=1 --out " + out.string() +
                                    (annotate ? " --annotate" : ""));
    ASSERT_EQ(result.exitCode, 0) << result.output;
    for (const char* stem : {"trace.visibility", "classify.mask", "composite.color"}) {
      const OIIO::ImageSpec png = specOf(out / (std::string(stem) + ".png"));
      int w = 0, h = 0;
      std::vector<std::string> channels;
      readExr(out / (std::string(stem) + ".exr"), w, h, channels);
      EXPECT_EQ(h, 72) << stem << ": the EXR stays raw";
      // Annotated, a small output is enlarged first (a whole factor) so that its labels fit.
      const int factor = annotate ? annotationEnlargement(96, 72) : 1;
      EXPECT_EQ(png.width, 96 * factor) << stem;
      if (annotate)
        EXPECT_GT(png.height, 72 * factor + 10) << stem << ": no annotation band";
      else
        EXPECT_EQ(png.height, 72) << stem;
    }
  }
  fs::remove_all(dir);
}

// `make readme-figures` found it: a script whose first file is a screenshot into a new
// --export folder.
TEST(LessonFigures, AScreenshotCreatesItsExportFolder) {
  REQUIRE_DISPLAY();
  const fs::path dir = scratchDirectory("screenshot_folder");
  const auto script = writeScript(dir, R"([{"eye_size": [160, 120]}, {"screenshot": "shot.png"}])");
  const auto result = runPenumbra("--script " + script.string() +
                                  " --export " + (dir / "new" / "folder").string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_EQ(specOf(dir / "new" / "folder" / "shot.png").width, 1280);
  fs::remove_all(dir);
}
