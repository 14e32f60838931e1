// Views that read at their defaults: error.absolute, error.signed and trace.cost start from
// the data's range (the 99th percentile of |value| over the written, i.e. non-zero, pixels;
// symmetric for the signed error), say "auto range", and every single-channel view draws a
// colour bar with that range (the layout report's colorbar lines). Oracle: the same run's
// EXRs, the percentile computed here by sorting. A range set by hand ends the auto range.
// Small outputs are enlarged (nearest neighbour, whole factor) before annotating.
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>

#include "figures/annotate.h"
#include "io/colormap.h"
#include "io/image_export.h"
#include "support/command.h"
#include "support/window_test.h"
#include "window/views/ui_view_settings.h"

namespace fs = std::filesystem;

namespace {

// Nearest rank over the non-zero finite magnitudes of channel `channel`, by a full sort.
double percentile99(const std::vector<float>& values, int channels, int channel) {
  std::vector<double> magnitudes;
  for (size_t i = size_t(channel); i < values.size(); i += size_t(channels))
    if (std::isfinite(values[i]) && values[i] != 0) magnitudes.push_back(std::fabs(double(values[i])));
  if (magnitudes.empty()) return -1;
  std::sort(magnitudes.begin(), magnitudes.end());
  size_t rank = 0;  // the smallest rank r with r >= 0.99 n
  while (double(rank) < 0.99 * double(magnitudes.size())) ++rank;
  return magnitudes[std::max<size_t>(rank, 1) - 1];
}

struct Bar {
  bool found = false;
  double low = 0, high = 0;
  int automatic = -1;
  std::string label;
};

// "layout LABEL: colorbar V at X Y size W H range LOW HIGH auto A label TEXT"
Bar colorBar(const std::string& output, const std::string& label, char view) {
  const std::string key = "layout " + label + ": colorbar " + std::string(1, view) + " at ";
  const size_t at = output.find(key);
  Bar bar;
  if (at == std::string::npos) return bar;
  std::istringstream line(output.substr(at + key.size(), output.find('\n', at) - at - key.size()));
  std::string word;
  double x, y, w, h;
  line >> x >> y >> word >> w >> h >> word >> bar.low >> bar.high >> word >> bar.automatic >> word;
  std::getline(line, bar.label);
  bar.found = word == "label" && w > 0 && h > 0;
  return bar;
}

}  // namespace

TEST(ViewColorBar, RobustRangeIsTheNearestRankPercentileOfTheWrittenMagnitudes) {
  std::vector<float> values;  // 200 pixels, two channels: 0..99 and -100..99 in channel 0
  for (int i = 0; i < 200; ++i) values.insert(values.end(), {float(i % 2 ? i - 100 : 0), 5});
  float low = 7, high = 7;
  ASSERT_TRUE(robustRange(values, 2, 0, false, low, high));
  EXPECT_EQ(low, 0);
  EXPECT_EQ(high, float(percentile99(values, 2, 0)));
  ASSERT_TRUE(robustRange(values, 2, 0, true, low, high));
  EXPECT_EQ(low, -high);
  EXPECT_EQ(high, 99);  // |-99| .. |99| ...: the 99th of 100 non-zero magnitudes
  const std::vector<float> none(20, 0);
  EXPECT_FALSE(robustRange(none, 1, 0, false, low, high));
  EXPECT_EQ(high, 99) << "untouched when nothing is written";
}

TEST(ViewColorBar, ErrorsAndCountsStartInAutoRangeVisibilitiesDoNot) {
  Output error{"absolute", "", GL_R32F, {"error"}, {0, 0, 1, Colormap::Perceptual, true}};
  EXPECT_TRUE(defaultViewSettings(error, 1).autoRange);
  Output visibility{"visibility", "", GL_R32F, {"visibility"}, {0, 0, 1, Colormap::Gray}};
  EXPECT_FALSE(defaultViewSettings(visibility, 1).autoRange);
}

TEST(ViewColorBar, SmallOutputsAreEnlargedByAWholeFactorBeforeAnnotating) {
  // hash_stats' pair histogram (64 x 64) and bit bars (16 x 160).
  EXPECT_EQ(annotationEnlargement(64, 64), 7);
  EXPECT_EQ(annotationEnlargement(16, 160), 5);
  EXPECT_EQ(annotationEnlargement(640, 480), 1);
  std::vector<std::uint8_t> rgb(size_t(64) * 64 * 3);
  for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = std::uint8_t(i * 37 % 251);
  Annotation annotation;
  annotation.bar = ColorBar{Colormap::Perceptual, 0, 2, "hash_stats.pairs: pairs"};
  annotation.caption = "cube · hash_stats.pairs · 64x64 · hash=md5_4";
  const AnnotatedImage out = annotateView(rgb, 64, 64, annotation);
  ASSERT_EQ(out.width, 448);
  EXPECT_EQ(out.height, 448 + annotationHeight(annotation, 448));
  ASSERT_EQ(out.rgb.size(), size_t(out.width) * out.height * 3);
  int wrong = 0;  // every texel a 7 x 7 block of its own colour
  for (int y = 0; y < 448; ++y)
    for (int x = 0; x < 448; ++x)
      for (int c = 0; c < 3; ++c)
        wrong += out.rgb[(size_t(y) * 448 + x) * 3 + c] != rgb[(size_t(y / 7) * 64 + x / 7) * 3 + c];
  EXPECT_EQ(wrong, 0);
  // The tall one: 80 x 800, centred on a 400-wide canvas, white beside it.
  const AnnotatedImage tall = annotateView(std::vector<std::uint8_t>(16 * 160 * 3, 0), 16, 160, annotation);
  ASSERT_EQ(tall.width, 400);
  EXPECT_EQ(tall.rgb[(size_t(400) * 400 + 10) * 3], 255);   // left of the image: canvas
  EXPECT_EQ(tall.rgb[(size_t(400) * 400 + 200) * 3], 0);    // the image
  // The caption fits unclipped at 400 wide where it needed four cut lines at 64.
  EXPECT_LT(annotationHeight(annotation, 400), annotationHeight(annotation, 64));
}

TEST(WindowColorBar, DefaultRangesOfErrorsAndCostAreTheDatasP99AndEveryViewDrawsABar) {
  REQUIRE_DISPLAY();
  const fs::path dir = scratchDirectory("view_colorbar");
  const auto script = writeScript(dir, R"([{"scene": "cube"}, {"eye_size": [160, 120]},
    {"set": {"reference.enabled": true, "reference.samples": 4, "error.method": "trace"}},
    {"two_views": true}, {"view": 0}, {"select_output": "trace.cost"}, {"channels": "R"},
    {"view": 1}, {"select_output": "error.absolute"}, {"wait": 2},
    {"view": 0}, {"export_view": "cost.exr"}, {"view": 1}, {"export_view": "absolute.exr"},
    {"print_layout": "first"},
    {"select_output": "error.signed"}, {"wait": 1}, {"export_view": "signed.exr"},
    {"print_layout": "second"},
    {"range": [0, 0.5]}, {"wait": 1}, {"print_layout": "third"}])");
  const auto result = runPenumbra("--script " + script.string() + " --export " + dir.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  int w = 0, h = 0;
  std::vector<std::string> names;
  const auto cost = readExr(dir / "cost.exr", w, h, names);
  ASSERT_EQ(w * h, 160 * 120);
  const int fetches = int(std::find(names.begin(), names.end(), "fetches") - names.begin());
  ASSERT_LT(fetches, int(names.size()));  // EXR keeps its channels in name order
  const int costChannels = int(names.size());
  const auto absolute = readExr(dir / "absolute.exr", w, h, names);
  const auto signedError = readExr(dir / "signed.exr", w, h, names);
  const double pCost = percentile99(cost, costChannels, fetches), pAbs = percentile99(absolute, 1, 0),
               pSigned = percentile99(signedError, 1, 0);
  ASSERT_GT(pCost, 2);  // some pixels traced, some errors: else the test shows nothing
  ASSERT_GT(pAbs, 0);
  ASSERT_GT(pSigned, 0);
  EXPECT_LT(pCost, 200) << "the declared 0..200 would look nearly solid";

  const Bar a = colorBar(result.output, "first", 'A'), b = colorBar(result.output, "first", 'B');
  ASSERT_TRUE(a.found) << result.output;
  ASSERT_TRUE(b.found) << result.output;
  EXPECT_EQ(a.low, 0);
  EXPECT_NEAR(a.high, pCost, 1e-5 * pCost);
  EXPECT_EQ(a.automatic, 1);
  EXPECT_NE(a.label.find("trace.cost: fetches"), std::string::npos) << a.label;
  EXPECT_NE(a.label.find("auto range"), std::string::npos) << a.label;
  EXPECT_EQ(b.low, 0);
  EXPECT_NEAR(b.high, pAbs, 1e-5 * pAbs);
  EXPECT_EQ(b.automatic, 1);
  const Bar s = colorBar(result.output, "second", 'B');
  ASSERT_TRUE(s.found) << result.output;
  EXPECT_NEAR(s.high, pSigned, 1e-5 * pSigned);
  EXPECT_NEAR(s.low, -pSigned, 1e-5 * pSigned);
  EXPECT_EQ(s.automatic, 1);
  const Bar hand = colorBar(result.output, "third", 'B');  // a range set by hand ends it
  ASSERT_TRUE(hand.found) << result.output;
  EXPECT_EQ(hand.low, 0);
  EXPECT_EQ(hand.high, 0.5);
  EXPECT_EQ(hand.automatic, 0);
  EXPECT_EQ(hand.label.find("auto range"), std::string::npos) << hand.label;
}
