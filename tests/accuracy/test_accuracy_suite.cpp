// The accuracy suite (docs/accuracy.md): every scene of tests/support/analytic_scenes.h rendered
// with the default parameters at 256x192 and compared with the exact analytic visibility.
#include <gtest/gtest.h>

#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "shared_inputs/light/auto_settings.h"
#include "support/analytic_scenes.h"
#include "support/gl_test.h"

namespace {

void report(const std::string& scene, const std::string& output, const AnalyticError& e) {
  std::printf("%-15s %-24s meanAbsInShadow %.4f max %.3f signed %+.4f umbra %.4f (%zu px, %zu umbra) bad %zu\n",
              scene.c_str(), output.c_str(), e.meanAbsInShadow, e.maxAbs, e.meanSigned,
              e.meanInUmbra, e.pixelsInShadow, e.pixelsInUmbra, e.outOfRange);
}

// Defaults at 256x192: the filtered result within 0.03 mean |error| in shadow on every
// case (contact included), the reference within 0.01 at 16x16 samples; nothing outside
// [0, 1], no NaN, in any method's output.
TEST(AccuracySuite, DefaultsHoldOnEveryCase) {
  for (const std::string& name : analyticSceneNames()) {
    std::vector<std::string> sets = {"reference.enabled=true", "reference.cache=false"};
    // Measurements: PENUMBRA_SUITE_SETS="stage.key=value stage.key=value" (not in CI).
    if (const char* extra = std::getenv("PENUMBRA_SUITE_SETS")) {
      std::istringstream words(extra);
      for (std::string word; words >> word;) sets.push_back(word);
    }
    PipelineRun run(makeAnalyticScene(name), sets, 256, 192);
    const std::vector<double> exact = analyticImage(run);
    const AutoSettings& chosen = lightAutoSettings(*run.frame);
    std::printf("%-15s auto: map %d, %d layers, %dx%d rays", name.c_str(), chosen.resolution,
                chosen.layers, chosen.raysPerSide, chosen.raysPerSide);
    for (const std::string& reason : run.frame->autoReasons) std::printf("; %s", reason.c_str());
    std::printf("\n");
    for (const char* output :
         {"filter.visibility", "trace.visibility", "reference.visibility", "hard_shadow.visibility"}) {
      const AnalyticError e = compareWithAnalytic(run.read(output), exact);
      report(name, output, e);
      if (std::getenv("PENUMBRA_SUITE_WORST")) {
        const auto values = run.read(output);
        const auto positions = run.read("gbuffer.wsPosition");
        const auto normals = run.read("gbuffer.wsNormal");
        for (size_t i = 0; i < exact.size(); ++i)
          if (exact[i] >= 0 && std::fabs(values[i] - exact[i]) > std::atof(std::getenv("PENUMBRA_SUITE_WORST")))
            std::printf("  px %zu,%zu p %.4f %.4f %.4f n %.3f %.3f %.3f exact %.3f got %.3f\n",
                        i % 256, i / 256, positions[4 * i], positions[4 * i + 1], positions[4 * i + 2],
                        normals[4 * i], normals[4 * i + 1], normals[4 * i + 2], exact[i], values[i]);
      }
      EXPECT_EQ(e.outOfRange, 0u) << name << " " << output;
      EXPECT_GT(e.pixelsInShadow, 100u) << name << ": the camera should see the shadow";
      if (output == std::string("filter.visibility")) {
        // The suite's target (docs/accuracy.md), met on every case since the filter's Gaussian is
        // cut at the penumbra's width (contact plates: 0.034 before) and light.normal_offset keeps
        // the box's side faces from shadowing themselves (box: 0.042 before).
        EXPECT_LE(e.meanAbsInShadow, 0.03) << name;
      }
      if (output == std::string("reference.visibility")) {
        EXPECT_LE(e.meanAbsInShadow, 0.01) << name;
      }
    }
  }
}

}  // namespace
