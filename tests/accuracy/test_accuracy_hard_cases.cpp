// Hard cases of docs/accuracy.md ("Hard cases"), each on generated scenes measured against the
// exact analytic visibility (tests/support/analytic_visibility.h):
// - a sheet nearly edge-on to the light, whose steps in the depth layers rise tens of texel
//   widths per texel (light_layers.close_risers, docs/decisions/115-...), and which `auto`
//   resolves with a map on which its image spans a dozen texels (docs/decisions/156-...);
// - two plates one above the other, where `auto` must choose three layers
//   (stages/shared_inputs/light/auto_settings.h step 5, docs/decisions/116-...).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <glm/gtc/matrix_transform.hpp>

#include "scene/mesh_builders.h"
#include "scene/scene_builtin.h"
#include "shared_inputs/light/auto_settings.h"
#include "support/analytic_scenes.h"
#include "support/gl_test.h"

namespace {

// The errors of `outputs` of one run against the exact visibility, each printed.
std::vector<AnalyticError> measureAll(const Scene& scene, const std::vector<std::string>& sets,
                                      const std::vector<std::string>& outputs, int width = 256,
                                      int height = 192) {
  PipelineRun run(scene, sets, width, height);
  const std::vector<double> exact = analyticImage(run);
  const AutoSettings& chosen = lightAutoSettings(*run.frame);
  std::string settings;
  for (const std::string& set : sets) settings += " " + set;
  std::vector<AnalyticError> errors;
  for (const std::string& output : outputs) {
    const std::vector<float> values = run.read(output);
    const AnalyticError e = compareWithAnalytic(values, exact);
    // Where to look with `penumbra trace` (not in CI): PENUMBRA_HARD_WORST=0.3 prints every
    // pixel (image coordinates, row 0 on top) whose error exceeds 0.3.
    if (const char* worst = std::getenv("PENUMBRA_HARD_WORST"))
      for (size_t i = 0; i < exact.size(); ++i)
        if (exact[i] >= 0 && std::fabs(values[i] - exact[i]) > std::atof(worst))
          std::printf("  pixel %zu,%zu exact %.3f got %.3f\n", i % size_t(width),
                      size_t(height) - 1 - i / size_t(width), exact[i], values[i]);
    std::printf("%s%s %s: mean |error| in shadow %.4f, signed %+.4f, umbra %+.4f (%zu pixels "
                "in shadow; auto: map %d, %d layers, %dx%d rays)\n",
                scene.name.c_str(), settings.c_str(), output.c_str(), e.meanAbsInShadow,
                e.meanSigned, e.meanInUmbra, e.pixelsInShadow, chosen.resolution, chosen.layers,
                chosen.raysPerSide, chosen.raysPerSide);
    errors.push_back(e);
  }
  return errors;
}

AnalyticError measure(const Scene& scene, const std::vector<std::string>& sets,
                      const std::string& output, int width = 256, int height = 192) {
  return measureAll(scene, sets, {output}, width, height).front();
}

// A 1 x 1 sheet at (0, 1, 0) standing almost upright under the suite's 1 x 1 light at y = 3:
// `degrees` from edge-on to the light's centre, turned about `axis`: z (the camera of the
// suite looks along the sheet's plane and sees its shadow on both sides; the sheet's image
// is narrow along the map's x) or x (it faces the camera; narrow along the map's y); a
// negative angle leans it the other way. Seen from the projection point behind the light the
// sheet's depth rises about 1 / tan(degrees) texel widths per texel across its image, at
// every map size.
Scene edgeOnSheet(float degrees, char axis = 'z') {
  Scene scene = makeAnalyticScene("plate_mid");
  scene.name = "edge-on sheet " + std::to_string(int(degrees)) + " degrees";
  if (axis != 'z') scene.name += std::string(" about ") + axis;
  scene.objects.resize(1);  // the receiver-only ground
  const glm::vec3 about = axis == 'z' ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
  const glm::mat4 place = glm::rotate(glm::translate(glm::mat4(1), {0, 1, 0}),
                                      glm::radians(90.0f - degrees), about);
  scene.objects.push_back({"sheet", makeQuad(1.0f, place), {0.3f, 0.5f, 0.9f}, false});
  return scene;
}

// The trace does not leak through a sheet nearly edge-on to the light (2, 4 and 8 degrees
// from edge-on): at a 1024^2 map the signed error against the exact visibility is within
// noise at 4 and 8 degrees (before: too bright by +0.059 and +0.037); at 2 degrees there,
// and at `auto`'s map (256^2, the sheet's image 2-8 texels wide), the leak is at most half of
// that with the risers left open (before: the same as open). The test below holds the
// ends of the sheet's image at `auto`'s map (docs/accuracy.md, "Hard cases").
TEST(AccuracyHardCases, EdgeOnSheetDoesNotLeak) {
  for (float degrees : {2.0f, 4.0f, 8.0f}) {
    const Scene scene = edgeOnSheet(degrees);
    for (const bool fineMap : {false, true}) {
      std::vector<std::string> sets = {"trace.rays=8"};
      if (fineMap) sets.push_back("light.resolution=1024");
      const AnalyticError traced = measure(scene, sets, "trace.visibility");
      EXPECT_GT(traced.pixelsInShadow, 2000u) << scene.name;
      EXPECT_EQ(traced.outOfRange, 0u) << scene.name;
      std::vector<std::string> open = sets;
      open.push_back("light_layers.close_risers=false");
      const AnalyticError leaking = measure(scene, open, "trace.visibility");
      if (fineMap && degrees >= 4.0f) {
        EXPECT_LE(std::fabs(traced.meanSigned), 0.006) << scene.name << ": too bright (a leak)";
      } else {
        EXPECT_LE(traced.meanSigned, 0.5 * leaking.meanSigned) << scene.name;
      }
      EXPECT_GT(leaking.meanSigned, traced.meanSigned + 0.01)
          << scene.name << ": the open staircase should leak";
    }
  }
}

// At a 256^2 map (where the sheet's image is only 2-8 texels wide) neither end of the image
// is half a step short, and no texel spans more than its footprint and the midpoints to its
// neighbours: on sheets 2-8 degrees from edge-on, leaning either way and narrow along either
// axis of the map, the trace at 8x8 rays is neither too bright (before, with the shallow
// end's near at the texel's centre: +0.018 at 2 degrees, +0.021 at 4 and -4) nor too dark
// (before, with far reaching the deeper neighbour's centre: -0.021 at -8 about x). At the
// defaults the filter is not worse than the unfiltered trace.
TEST(AccuracyHardCases, EdgeOnSheetDoesNotLeakAtACoarseMap) {
  const std::vector<std::pair<float, char>> sheets = {
      {2.0f, 'z'}, {4.0f, 'z'}, {8.0f, 'z'}, {-4.0f, 'z'}, {4.0f, 'x'}, {-8.0f, 'x'}};
  for (const auto& [degrees, axis] : sheets) {
    const Scene scene = edgeOnSheet(degrees, axis);
    const AnalyticError traced =
        measure(scene, {"trace.rays=8", "light.resolution=256"}, "trace.visibility");
    EXPECT_GT(traced.pixelsInShadow, 2000u) << scene.name;
    EXPECT_LE(traced.meanSigned, 0.008) << scene.name << ": too bright (a leak)";
    EXPECT_GE(traced.meanSigned, -0.015) << scene.name << ": too dark";
    const std::vector<AnalyticError> defaults =
        measureAll(scene, {}, {"trace.visibility", "filter.visibility"});
    EXPECT_LE(defaults[1].meanAbsInShadow, defaults[0].meanAbsInShadow + 0.005) << scene.name;
  }
}

// A sheet turned about an axis across the light's rays, `degrees` from edge-on to the light's
// centre: its plane holds the ray from the light's centre through `at` before the turn.
Scene turnedSheet(float degrees, glm::vec3 at, glm::vec3 across, float size) {
  Scene scene = makeAnalyticScene("plate_mid");
  scene.name = "sheet " + std::to_string(size).substr(0, 3) + " turned " +
               std::to_string(int(degrees)) + " degrees from edge-on";
  scene.objects.resize(1);
  const glm::vec3 toLight = glm::normalize(scene.light.center - at);
  const glm::vec3 axis = glm::normalize(glm::cross(toLight, across));
  const glm::vec3 edgeOnNormal = glm::normalize(glm::cross(toLight, axis));
  const glm::mat4 turn = glm::rotate(glm::mat4(1), glm::radians(degrees), axis);
  const glm::vec3 normal = glm::vec3(turn * glm::vec4(edgeOnNormal, 0));
  // makeQuad's normal is +y: turn +y onto `normal`.
  const glm::vec3 y(0, 1, 0);
  glm::mat4 place = glm::translate(glm::mat4(1), at);
  if (glm::length(glm::cross(y, normal)) > 1e-6f)
    place = glm::rotate(place, std::acos(glm::clamp(glm::dot(y, normal), -1.0f, 1.0f)),
                        glm::normalize(glm::cross(y, normal)));
  scene.objects.push_back({"sheet", makeQuad(size, place), {0.3f, 0.5f, 0.9f}, false});
  return scene;
}

// `auto` resolves a steep sheet: with the defaults the filtered trace meets the 0.03 target
// (mean |error| in shadow against the exact visibility) on sheets 1-12 degrees from edge-on,
// leaning either way about two axes, and on smaller sheets turned about a third, higher up
// (before, with the map from the penumbrae alone, 256^2: over 0.03 on 15 of these 23 and
// 0.0300 on two more, up to 0.066 at 1 degree), and is never worse than the unfiltered trace
// by more than 0.005.
// The map it takes gives the sheet's image at least 12 texels (or is 2048); a rod lying
// across the light's rays, whose image is as narrow, is not steep and keeps the map its
// penumbrae ask for.
TEST(AccuracyHardCases, AutoMapResolvesSteepSheets) {
  std::vector<Scene> scenes;
  for (char axis : {'z', 'x'})
    for (float degrees : {1.0f, 2.0f, 3.0f, 5.0f, 7.0f, 10.0f, 12.0f, -3.0f, -6.0f, -10.0f})
      scenes.push_back(edgeOnSheet(degrees, axis));
  for (float degrees : {2.0f, 5.0f, 9.0f})
    scenes.push_back(turnedSheet(degrees, {0.1f, 1.4f, 0.1f}, {1, 0, 1}, 0.6f));
  for (const Scene& scene : scenes) {
    PipelineRun run(scene, {}, 256, 192);
    const AutoSettings& chosen = lightAutoSettings(*run.frame);
    const std::vector<double> exact = analyticImage(run);
    const AnalyticError filtered = compareWithAnalytic(run.read("filter.visibility"), exact);
    const AnalyticError traced = compareWithAnalytic(run.read("trace.visibility"), exact);
    std::printf("%s: map %d (the image %.2f texels), filtered %.4f signed %+.4f, trace %.4f\n",
                scene.name.c_str(), chosen.resolution,
                chosen.narrowestOccluderImage * chosen.resolution, filtered.meanAbsInShadow,
                filtered.meanSigned, traced.meanAbsInShadow);
    EXPECT_GT(filtered.pixelsInShadow, 1000u) << scene.name;
    const double imageTexels = chosen.narrowestOccluderImage * chosen.resolution;
    EXPECT_TRUE(chosen.resolution == 2048 || imageTexels >= 12.0) << scene.name;
    EXPECT_LE(filtered.meanAbsInShadow, 0.03) << scene.name;
    EXPECT_LE(filtered.meanAbsInShadow, traced.meanAbsInShadow + 0.005) << scene.name;
  }
  Scene rod = makeAnalyticScene("plate_mid");
  rod.name = "rod lying across the light's rays";
  rod.objects.resize(1);
  const glm::mat4 across = glm::rotate(glm::translate(glm::mat4(1), {0, 1, 0}), 0.5f, {0, 1, 0});
  rod.objects.push_back({"rod", makeBox({1.2f, 0.03f, 0.03f}, across), {0.3f, 0.5f, 0.9f}, false});
  PipelineRun run(rod, {}, 256, 192);
  const AutoSettings& chosen = lightAutoSettings(*run.frame);
  EXPECT_EQ(chosen.resolution, 256) << rod.name << ": not steep, its penumbrae need only 256";
  const std::vector<double> rodExact = analyticImage(run);
  const AnalyticError rodError = compareWithAnalytic(run.read("filter.visibility"), rodExact);
  EXPECT_LE(rodError.meanAbsInShadow, 0.03) << rod.name;
}

// A sheet exactly edge-on to the light's centre is in no map (its image is a line): `auto`
// does not raise the map for it (no size would show it) and warns, naming it; one degree
// from edge-on it is seen (7.45 texels at 2048) and there is no warning.
TEST(AccuracyHardCases, AutoWarnsOfASheetEdgeOnToTheLightsCentre) {
  for (const float degrees : {0.0f, 1.0f}) {
    PipelineRun run(edgeOnSheet(degrees), {"trace.rays=1"}, 128, 96);
    const AutoSettings& chosen = lightAutoSettings(*run.frame);
    bool warned = false;
    for (const std::string& reason : run.frame->autoReasons)
      warned = warned || reason.find("WARNING: occluder 'sheet' is edge-on") != std::string::npos;
    EXPECT_EQ(warned, degrees == 0.0f) << degrees << " degrees";
    EXPECT_EQ(chosen.resolution, degrees == 0.0f ? 256 : 2048) << degrees << " degrees";
  }
}

// Two plates one above the other, the upper smaller and offset (the layout of Atty 2006's
// Eq 3 overlap case, assets/scenes/two_plates.json): two layers fill the space between them.
Scene twoPlates(float lowerY, float upperY, glm::vec3 upperOffset) {
  Scene scene = makeAnalyticScene("plate_mid");
  scene.name = "two plates at " + std::to_string(lowerY).substr(0, 4) + " and " +
               std::to_string(upperY).substr(0, 4);
  scene.objects.resize(1);
  scene.objects.push_back({"lower", makeQuad(1.0f, glm::translate(glm::mat4(1), {0, lowerY, 0})),
                           {0.3f, 0.5f, 0.9f}, false});
  scene.objects.push_back(
      {"upper", makeQuad(0.5f, glm::translate(glm::mat4(1), glm::vec3(0, upperY, 0) + upperOffset)),
       {0.9f, 0.5f, 0.3f}, false});
  scene.light = {{0.35f, 3, 0.2f}, {0, -1, 0}, {0, 0, -1}, 1.2f, 0.8f};
  scene.camera = {{0.6f, 4.2f, 3.4f}, {0.2f, 0.2f, 0.1f}, {0, 1, 0}, 45};
  return scene;
}

// `auto` chooses three layers on two plates at different heights (before: two, from the two
// surfaces on a light ray), and the filtered error drops against two layers.
TEST(AccuracyHardCases, AutoChoosesThreeLayersForPlatesOneAboveTheOther) {
  for (const Scene& scene : {twoPlates(0.9f, 1.7f, {0, 0, 0}), twoPlates(0.5f, 1.5f, {0.2f, 0, -0.1f})}) {
    PipelineRun run(scene, {}, 256, 192);
    const AutoSettings& chosen = lightAutoSettings(*run.frame);
    for (const std::string& reason : run.frame->autoReasons) std::printf("  %s\n", reason.c_str());
    EXPECT_EQ(chosen.layers, 3) << scene.name;
    EXPECT_LE(chosen.depthComplexity, 2) << scene.name << ": the old rule alone says two";
    const std::vector<double> exact = analyticImage(run);
    const AnalyticError autoError = compareWithAnalytic(run.read("filter.visibility"), exact);
    const AnalyticError two = measure(scene, {"light.layers=two"}, "filter.visibility");
    std::printf("%s: filtered, auto (three layers) %.4f signed %+.4f; two layers %.4f signed %+.4f\n",
                scene.name.c_str(), autoError.meanAbsInShadow, autoError.meanSigned,
                two.meanAbsInShadow, two.meanSigned);
    EXPECT_LE(autoError.meanAbsInShadow, two.meanAbsInShadow - 0.002) << scene.name;
    EXPECT_LE(autoError.meanAbsInShadow, 0.03) << scene.name;
  }
}

// Where occluders do not lie one behind the other the choice stays two layers: one closed box
// (its two surfaces on a ray bound one solid), one sheet, and the built-in scenes but engine,
// which keeps three (more than two surfaces on one light ray).
TEST(AccuracyHardCases, AutoKeepsTwoLayersForSingleOccluders) {
  std::vector<std::pair<Scene, int>> cases;
  cases.emplace_back(makeAnalyticScene("box"), 2);
  cases.emplace_back(makeAnalyticScene("tilted_plate"), 2);
  for (const char* name : {"cube", "plate", "spheres"}) cases.emplace_back(makeBuiltinScene(name), 2);
  cases.emplace_back(makeBuiltinScene("engine"), 3);
  for (const auto& [scene, layers] : cases) {
    // A cheap run: `auto` decides from the scene whatever the fixed settings.
    PipelineRun run(scene, {"light.resolution=256", "trace.rays=1"}, 256, 192);
    const AutoSettings& chosen = lightAutoSettings(*run.frame);
    std::printf("%s: %d layers, %d of %d probes with free space between two occluders\n",
                scene.name.c_str(), chosen.layers, chosen.separateOccluderProbes, chosen.probes);
    EXPECT_EQ(chosen.layers, layers) << scene.name;
  }
}

}  // namespace
