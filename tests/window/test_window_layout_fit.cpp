// The window at UI scale 1, 1.5 and 2 in 1280 x 800 and 1920 x 1080 windows, measured from
// what ImGui drew (`print_layout`: every run of text with its clip and frame, every image;
// app/window/ui_layout_report.h): no text cut by its frame or clip, none drawn over other
// text, and the views never smaller than the stated minimum, kMinViewsShare of the width
// (app/window/window_app.cpp; the side panels collapse into one column first). Before, at
// 1.5 the eye/target/light fields lost their last digits and the settings path was cut, at
// 2 the fields' digits were cut in half, the inspector split numbers after their '.' (at
// scale 1 and 1.5 too, where a value did not fit the column), and
// in a 1280 x 800 window view A's image shrank to 360 x 314.
//
// Also: a parameter under `auto` shows what auto chose ("256 (auto)"), not its hand value;
// and a lesson played interactively sits below the views, not over them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "support/command.h"
#include "support/window_test.h"

namespace fs = std::filesystem;

namespace {

struct Rect {
  float x0, y0, x1, y1;
  bool intersects(const Rect& o) const {
    return x0 + 0.5f < o.x1 && o.x0 + 0.5f < x1 && y0 + 0.5f < o.y1 && o.y0 + 0.5f < y1;
  }
  float width() const { return x1 - x0; }
  float height() const { return y1 - y0; }
};

struct Text {
  std::string window, text;
  Rect extent, clip, ink, frame;
  float cutX, cutY;
  bool scrollsX, scrollsY, ellipsis;
};

struct Drawn {
  std::vector<std::pair<std::string, Rect>> windows, images;
  std::vector<Text> texts;
};

Drawn layoutOf(const std::string& output, const std::string& label) {
  Drawn drawn;
  const std::string n = "(-?[0-9.]+)";
  const std::regex window("layout " + label + ": window (.+) at " + n + " " + n + " size " + n + " " + n + " contents.*");
  const std::regex image("layout " + label + ": image (.+) at " + n + " " + n + " size " + n + " " + n + " clip " +
                         n + " " + n + " " + n + " " + n);
  const std::regex text("layout " + label + ": text (.+) at " + n + " " + n + " size " + n + " " + n + " clip " + n +
                        " " + n + " " + n + " " + n + " ink " + n + " " + n + " " + n + " " + n + " frame " + n +
                        " " + n + " " + n + " " + n + " cut " + n + " " + n +
                        " scrolls ([01]) ([01]) ellipsis ([01]) \"(.*)\"");
  const auto f = [](const std::ssub_match& m) { return std::stof(m.str()); };
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) {
    std::smatch m;
    if (std::regex_match(line, m, window)) {
      drawn.windows.push_back({m[1], {f(m[2]), f(m[3]), f(m[2]) + f(m[4]), f(m[3]) + f(m[5])}});
    } else if (std::regex_match(line, m, image)) {
      drawn.images.push_back({m[1], {f(m[6]), f(m[7]), f(m[8]), f(m[9])}});  // its clip: the region
    } else if (std::regex_match(line, m, text)) {
      Text t;
      t.window = m[1];
      t.extent = {f(m[2]), f(m[3]), f(m[2]) + f(m[4]), f(m[3]) + f(m[5])};
      t.clip = {f(m[6]), f(m[7]), f(m[8]), f(m[9])};
      t.ink = {f(m[10]), f(m[11]), f(m[12]), f(m[13])};
      t.frame = {f(m[14]), f(m[15]), f(m[16]), f(m[17])};
      t.cutX = f(m[18]);
      t.cutY = f(m[19]);
      t.scrollsX = m[20] == "1";
      t.scrollsY = m[21] == "1";
      t.ellipsis = m[22] == "1";
      t.text = m[23];
      drawn.texts.push_back(t);
    }
  }
  return drawn;
}

const Rect* windowNamed(const Drawn& drawn, const std::string& name) {
  for (const auto& [window, rect] : drawn.windows)
    if (window == name) return &rect;
  return nullptr;
}

// Every way a run of text can fail to show whole, as the report measures it. Text in a
// window that scrolls may be cut at the scrolling edge (the user scrolls to it).
std::vector<std::string> textProblems(const Drawn& drawn) {
  std::vector<std::string> problems;
  const auto describe = [](const Text& t) { return "'" + t.text + "' in " + t.window; };
  for (const Text& t : drawn.texts) {
    if (t.cutX > 0 && !t.scrollsX) problems.push_back(describe(t) + ": " + std::to_string(t.cutX) + " px cut off sideways");
    if (t.cutY > 0 && !t.scrollsY) problems.push_back(describe(t) + ": " + std::to_string(t.cutY) + " px cut off vertically");
    if (t.ellipsis) problems.push_back(describe(t) + ": shortened with an ellipsis");
    // Glyphs wholly past a frame are not drawn at all: a pen box past the frame lost some.
    if (!t.scrollsX && t.frame.width() > 0 && (t.extent.x1 > t.frame.x1 + 0.5f || t.extent.x0 < t.frame.x0 - 0.5f))
      problems.push_back(describe(t) + ": runs past its frame (" + std::to_string(t.extent.x1) + " > " +
                         std::to_string(t.frame.x1) + "): glyphs lost");
  }
  // A number wrapped after its point ("B 0." / "25098": ImGui's wrapping may break after
  // any '.') reads as two numbers.
  const auto digit = [](char c) { return c >= '0' && c <= '9'; };
  for (size_t i = 0; i + 1 < drawn.texts.size(); ++i) {
    const std::string &a = drawn.texts[i].text, &b = drawn.texts[i + 1].text;
    if (a.size() >= 2 && a.back() == '.' && digit(a[a.size() - 2]) && !b.empty() && digit(b[0]) &&
        drawn.texts[i].window == drawn.texts[i + 1].window && drawn.texts[i + 1].extent.y0 > drawn.texts[i].extent.y0)
      problems.push_back(describe(drawn.texts[i]) + ": a number split over two lines ('" + b + "')");
  }
  for (size_t i = 0; i < drawn.texts.size(); ++i)
    for (size_t j = i + 1; j < drawn.texts.size(); ++j) {
      const Text &a = drawn.texts[i], &b = drawn.texts[j];
      if (a.window == b.window && a.ink.width() > 0 && b.ink.width() > 0 && a.ink.intersects(b.ink))
        problems.push_back(describe(a) + " and '" + b.text + "' overlap");
    }
  return problems;
}

struct Fit {
  float scale;
  int width, height;
};

class LayoutFit : public ::testing::TestWithParam<Fit> {};

}  // namespace

// The pipeline panel at its top (scene, camera, light) and at the light stage (its `auto`
// controls), the chart tab, the inspector with a picked texel and its ray, and the 2 x 2 grid.
TEST_P(LayoutFit, NoTextCutOrOverlappingAndTheViewsKeepTheirMinimum) {
  REQUIRE_DISPLAY();
  const Fit fit = GetParam();
  const fs::path dir = scratchDirectory("layout_fit");
  const std::string scale = std::to_string(fit.scale);
  const auto script = writeScript(dir, R"([{"ui_scale": )" + scale + R"(}, {"eye_size": [160, 120]},
    {"pick": [100, 40]}, {"wait": 3}, {"print_layout": "top"},
    {"select_stage": "light"}, {"wait": 2}, {"print_layout": "light"},
    {"speed_error": true}, {"wait": 2}, {"print_layout": "chart"},
    {"select_output": "composite.color"}, {"speed_error": false}, {"wait": 2}, {"print_layout": "inspector"},
    {"layout": "grid"}, {"wait": 2}, {"print_layout": "grid"}])");
  const auto result = runPenumbra("--width " + std::to_string(fit.width) + " --height " + std::to_string(fit.height) +
                                  " --script " + script.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const std::string where = "scale " + scale + ", " + std::to_string(fit.width) + "x" + std::to_string(fit.height);
  for (const char* label : {"top", "light", "chart", "inspector"}) {
    const Drawn drawn = layoutOf(result.output, label);
    ASSERT_GT(drawn.texts.size(), 10u) << where << ", " << label << "\n" << result.output;
    for (const std::string& problem : textProblems(drawn)) ADD_FAILURE() << where << ", " << label << ": " << problem;
    // The stated minimum: the views get half the window's width; view A's image region (one
    // view) half the width less its paddings and borders, and half the window's height.
    const Rect* views = windowNamed(drawn, "##views");
    ASSERT_NE(views, nullptr) << where;
    EXPECT_GE(views->width(), 0.5f * float(fit.width) - 1) << where << ", " << label;
    if (std::string(label) == "light" || std::string(label) == "chart") continue;  // the view shows light.light, a buffer
    const Rect* image = nullptr;
    for (const auto& [window, rect] : drawn.images)
      if (window.rfind("##views/view_A", 0) == 0) image = &rect;
    ASSERT_NE(image, nullptr) << where << ", " << label << "\n" << result.output;
    EXPECT_GE(image->width(), 0.5f * float(fit.width) - 48) << where << ", " << label;
    EXPECT_GE(image->height(), 0.5f * float(fit.height)) << where << ", " << label;
  }
  // The 2 x 2 grid: four images, every toolbar's text whole.
  const Drawn grid = layoutOf(result.output, "grid");
  for (const std::string& problem : textProblems(grid)) ADD_FAILURE() << where << ", grid: " << problem;
  int cells = 0;
  for (const auto& [window, rect] : grid.images) cells += window.rfind("##views/view_", 0) == 0;
  EXPECT_EQ(cells, 4) << where;
  // The inspector is shown (in one column with the pipeline where the window is narrow).
  bool picked = false;
  for (const Text& t : layoutOf(result.output, "inspector").texts) picked |= t.text.find(") in 160x120") != std::string::npos;
  EXPECT_TRUE(picked) << where << ": the inspector's pick line was not drawn";
}

INSTANTIATE_TEST_SUITE_P(ScalesAndSizes, LayoutFit,
                         ::testing::Values(Fit{1, 1280, 800}, Fit{1.5f, 1280, 800}, Fit{2, 1280, 800},
                                           Fit{1, 1920, 1080}, Fit{1.5f, 1920, 1080}, Fit{2, 1920, 1080}),
                         [](const ::testing::TestParamInfo<Fit>& info) {
                           return "scale" + std::to_string(int(info.param.scale * 10)) + "_" +
                                  std::to_string(info.param.width) + "x" + std::to_string(info.param.height);
                         });

// Under `auto` the map-size slider and the layers box show what auto chose (the auto.*
// counters), greyed and marked "(auto)"; set by hand, they show the hand value. (Before,
// they showed the declared 512 and "two" while auto chose 256, or three layers.)
TEST(LayoutAuto, AutoControlsShowTheChosenValue) {
  REQUIRE_DISPLAY();
  const fs::path dir = scratchDirectory("layout_auto");
  // On the cube in view, auto chooses a 256 map (declared: 512).
  const auto script = writeScript(dir, R"([{"eye_size": [160, 120]}, {"select_stage": "light"}, {"wait": 3},
    {"print_counters": "auto"}, {"print_layout": "auto"},
    {"set": {"light.resolution": 1024, "light.layers": "one"}}, {"select_stage": "light"}, {"wait": 3},
    {"print_layout": "hand"}])");
  const auto result = runPenumbra("--script " + script.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(result.output, m, std::regex("auto\\.resolution ([0-9]+)"))) << result.output;
  const std::string resolution = m[1];
  ASSERT_TRUE(std::regex_search(result.output, m, std::regex("auto\\.layers ([0-9]+)"))) << result.output;
  const std::string layers = std::vector<std::string>{"one", "two", "three"}.at(size_t(std::stoi(m[1]) - 1));
  const auto shown = [&](const std::string& label, const std::string& text) {
    for (const Text& t : layoutOf(result.output, label).texts)
      if (t.window.rfind("Pipeline", 0) == 0 && t.text == text) return true;
    return false;
  };
  EXPECT_TRUE(shown("auto", resolution + " (auto)")) << "the map size slider does not show auto's " << resolution;
  EXPECT_TRUE(shown("auto", layers + " (auto)")) << "the layers box does not show auto's " << layers;
  EXPECT_FALSE(shown("auto", "512")) << "the declared map size is shown under auto";
  EXPECT_TRUE(shown("hand", "1024"));
  EXPECT_TRUE(shown("hand", "one"));
  EXPECT_FALSE(shown("hand", resolution + " (auto)"));
}

// Played interactively (`penumbra lesson FILE` without --export), the lesson strip lies
// below the views: no view's image region reaches under it. (Before, it covered the
// bottom 180 px of the views, centred over them.)
TEST(LayoutLesson, TheLessonStripDoesNotCoverTheViews) {
  REQUIRE_DISPLAY();
  const fs::path dir = scratchDirectory("layout_lesson");
  const fs::path lesson = dir / "lesson.json";
  std::ofstream(lesson) << R"([{"lesson": "A test lesson whose title is long enough to be cut by a title bar in a 1280 x 800 window"}, {"eye_size": [160, 120]}, {"two_views": true},
    {"say": "First step: a text long enough to wrap over several lines of the strip, so that the strip's height counts. The dragon's neck, in the thesis' Fig 3.5, lies at the bottom of the view."},
    {"wait": 2}, {"print_layout": "lesson"},
    {"say": "Second step: waits for the student."}])";
  const auto result = runPenumbra("lesson " + lesson.string() + " --screenshot " + (dir / "shot.png").string() +
                                  " --frames 40");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const Drawn drawn = layoutOf(result.output, "lesson");
  const Rect* strip = nullptr;
  for (const auto& [window, rect] : drawn.windows)
    if (window.find("###lesson") != std::string::npos && window.find('/') == std::string::npos) strip = &rect;
  ASSERT_NE(strip, nullptr) << result.output;
  const Rect* views = windowNamed(drawn, "##views");
  ASSERT_NE(views, nullptr) << result.output;
  EXPECT_FALSE(strip->intersects(*views)) << "the lesson strip lies over the views";
  int images = 0;
  for (const auto& [window, rect] : drawn.images)
    if (window.rfind("##views/", 0) == 0) {
      ++images;
      EXPECT_FALSE(strip->intersects(rect)) << "the lesson strip covers " << window;
    }
  EXPECT_EQ(images, 2) << result.output;
  // Its text is whole: wrapped inside the strip, nothing cut sideways.
  bool said = false;
  for (const Text& t : drawn.texts)
    if (t.window.find("###lesson") != std::string::npos) {
      said |= t.text.rfind("First step", 0) == 0;
      EXPECT_EQ(t.cutX, 0) << t.text;
    }
  EXPECT_TRUE(said) << result.output;
}
