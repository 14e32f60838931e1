// Stage `pcss` (Fernando 2005): its blocker search against a brute-force CPU average over the
// same taps of the same near layer, its visibility on the plate (a planar blocker parallel
// to the light, where the light's cone cut at the blocker makes PCF exact up to the taps and
// the map), and finite visibility in [0, 1] on every built-in and stress scene.
#include <gtest/gtest.h>

#include <cmath>

#include "gl/tap_patterns.h"
#include "scene/scene_builtin.h"
#include "scene/scene_stress.h"
#include "support/gl_test.h"
#include "support/rect_visibility.h"

namespace {

// A constant bias only (the CPU applies it the same way: the receiver moves that far towards
// the light), so that a receiver's own surface lies clearly behind its biased tangent plane;
// no per-pixel shift, so the taps are the table's.
constexpr double kBias = 0.01;
const std::vector<std::string> kExact = {"light.bias=0.01", "light.adaptive_bias=false",
                                         "pcss.shift=false"};

struct BlockerSearch {
  int checked = 0, skippedAsTies = 0, withBlockers = 0;
};

BlockerSearch checkBlockerSearch(const std::string& sceneName, const std::string& pattern) {
  std::vector<std::string> sets = kExact;
  sets.push_back("pcss.pattern=" + pattern);
  const int w = 96, h = 72;
  PipelineRun run(makeBuiltinScene(sceneName), sets, w, h);
  const LightFrame& f = run.frame->light;
  const auto nearLayer = run.read("light_layers.near");
  const int size = run.frame->texture("light_layers.near").width();
  const auto wsPosition = run.read("gbuffer.wsPosition");
  const auto wsNormal = run.read("gbuffer.wsNormal");
  const auto searchRadius = run.read("pcss.searchRadius");
  const auto blockerDepth = run.read("pcss.blockerDepth");
  const TapPattern taps = pattern == "regular" ? TapPattern::Regular : TapPattern::Poisson;
  const std::vector<glm::vec2> searchTaps =
      squareTaps(taps, run.pipeline->param("pcss.search_taps").asInt());

  // Brute force: the nearest occluder over every texel, the cone, every tap.
  double nearestLs = 1;
  for (float v : nearLayer) nearestLs = std::min(nearestLs, double(v));
  const double zNear = f.zNear, zFar = f.zFar;
  const auto toZ = [&](double ls) { return zNear + ls * (zFar - zNear); };
  const double zNearest = toZ(nearestLs);
  BlockerSearch result;
  for (int pixel = 0; pixel < w * h; ++pixel) {
    const float* p = &wsPosition[size_t(4 * pixel)];
    if (p[3] <= 0) continue;
    const glm::vec4 clip = f.lightClipFromWorld * glm::vec4(p[0], p[1], p[2], 1);
    const glm::dvec2 uv = glm::dvec2(clip.x, clip.y) / double(clip.w) * 0.5 + 0.5;
    const double z = clip.w;
    if (uv.x < 0 || uv.y < 0 || uv.x >= 1 || uv.y >= 1 || z <= zNear) continue;
    // The light's cone from the receiver, cut at the nearest occluder: the light fills the
    // map at its own plane zL, so the cut at zc is a square of half-width
    // (zL/2)(z - zc) / ((z - zL) zc) around the point of the receiver-to-light-centre line
    // at zc, whose uv is 0.5 + (uv - 0.5) z (zc - zL) / ((z - zL) zc).
    const double half = zNearest < z ? 0.5 * zNear * (z - zNearest) / ((z - zNear) * zNearest) : 0;
    const glm::dvec2 centre = zNearest < z ? 0.5 + (uv - 0.5) * (z * (zNearest - zNear) / ((z - zNear) * zNearest))
                                           : uv;
    EXPECT_NEAR(searchRadius[size_t(pixel)], half * size, 1e-3 * (1 + half * size)) << "pixel " << pixel;
    const double lsReceiver = (z - kBias - zNear) / (zFar - zNear);
    // A receiver facing the light centre is blocked only by points in front of its tangent
    // plane: a texel's point is on the ray from the projection point through its centre.
    const glm::dvec3 wsP = glm::dvec3(p[0], p[1], p[2]) - kBias * glm::dvec3(f.forward);
    const glm::dvec3 wsN(wsNormal[4 * size_t(pixel)], wsNormal[4 * size_t(pixel) + 1],
                         wsNormal[4 * size_t(pixel) + 2]);
    const bool plane = glm::dot(wsN, glm::dvec3(run.scene.light.center) - wsP) > 0;
    const auto inFront = [&](glm::ivec2 texel, double ls) {
      const glm::dvec2 ndc = (glm::dvec2(texel) + 0.5) / double(size) * 2.0 - 1.0;
      const glm::dvec3 ray = glm::dvec3(f.forward) + ndc.x * double(f.tanHalfFovX) * glm::dvec3(f.right) +
                             ndc.y * double(f.tanHalfFovY) * glm::dvec3(f.up);
      return glm::dot(wsN, glm::dvec3(f.wsProjectionPoint) + toZ(ls) * ray - wsP);
    };
    double sum = 0;
    int blockers = 0;
    bool tie = false;
    for (const glm::vec2& t : searchTaps) {
      const glm::dvec2 at = centre + half * glm::dvec2(t);
      if (at.x < 0 || at.y < 0 || at.x >= 1 || at.y >= 1) continue;
      const glm::dvec2 texelF = at * double(size);
      // Taps on a texel border or depths equal to the receiver's are float ties: skip them.
      if (std::abs(texelF.x - std::round(texelF.x)) < 1e-4 || std::abs(texelF.y - std::round(texelF.y)) < 1e-4)
        tie = true;
      const glm::ivec2 texel(texelF);
      const double ls = nearLayer[size_t(texel.y * size + texel.x)];
      if (std::abs(ls - lsReceiver) < 1e-5) tie = true;
      const double front = plane ? inFront(texel, ls) : 1.0;
      if (std::abs(front) < 1e-4) tie = true;
      if (ls < lsReceiver && front > 0) sum += toZ(ls), ++blockers;
    }
    if (tie) { ++result.skippedAsTies; continue; }
    ++result.checked;
    const double expected = blockers ? (sum / blockers - zNear) / (zFar - zNear) : 0;
    EXPECT_NEAR(blockerDepth[size_t(pixel)], expected, 1e-5) << sceneName << " pixel " << pixel
                                                              << " blockers " << blockers;
    result.withBlockers += blockers > 0;
  }
  return result;
}

}  // namespace

// Step 1-2: the search region and the average blocker depth equal a brute-force average over
// the same taps (Poisson and regular) of the same near layer, blockers in front of the
// receiver's tangent plane (world space, double).
TEST(Pcss, BlockerSearchEqualsBruteForceAverage) {
  for (const char* scene : {"cube", "spheres"})
    for (const char* pattern : {"poisson", "regular"}) {
      const BlockerSearch r = checkBlockerSearch(scene, pattern);
      std::printf("%s, %s taps: %d pixels checked (%d with blockers), %d skipped as float ties\n",
                  scene, pattern, r.checked, r.withBlockers, r.skippedAsTies);
      EXPECT_GT(r.withBlockers, 200);
      EXPECT_GT(r.checked, 20 * r.skippedAsTies);
    }
}

// Steps 3-4 on the plate: the blocker is one plane parallel to the light, so the average
// blocker depth is the plate's and the light's cone cut there is exactly the part of the
// plate's plane that matters: PCF over it is the exact visibility, up to the taps and the
// map's half-texel discretization of the plate. A regular n x n grid places an edge across
// the region to within half a row of taps: error up to 1/(2n), about 1/(4n) on average.
TEST(Pcss, PlateVisibilityNearExact) {
  const ParallelRect plate{{0, 1, 0}, 0.5, 0.5};
  double previous = 1;
  for (int taps : {4, 8}) {
    const std::string n = std::to_string(taps);
    PipelineRun run(makeBuiltinScene("plate"), {"pcss.pattern=regular", "pcss.search_taps=" + n,
                                                "pcss.filter_taps=" + n}, 128, 128);
    const Scene& scene = run.scene;
    const LightFrame& f = run.frame->light;
    const RectLight light{glm::dvec3(scene.light.center), glm::dvec3(f.right), glm::dvec3(f.up),
                          glm::dvec3(f.forward), 0.5 * scene.light.width, 0.5 * scene.light.height};
    const auto wsPosition = run.read("gbuffer.wsPosition");
    const auto visibility = run.read("pcss.visibility");
    double sum = 0;
    int counted = 0;
    for (size_t i = 0; i < visibility.size(); ++i) {
      const float* p = &wsPosition[4 * i];
      if (p[3] <= 0 || std::abs(p[1]) > 1e-4) continue;  // ground pixels only
      const double exact = 1 - hiddenFraction(light, plate, glm::dvec3(p[0], p[1], p[2]));
      if (exact >= 1 && visibility[i] >= 1) continue;
      sum += std::abs(visibility[i] - exact), ++counted;
    }
    const double mean = sum / std::max(counted, 1);
    std::printf("plate, %dx%d regular taps: mean |visibility error| over %d shadowed ground pixels %.4f\n",
                taps, taps, counted, mean);
    EXPECT_GT(counted, 1000);
    EXPECT_LT(mean, 1.0 / (2 * taps));
    EXPECT_LT(mean, previous);
    previous = mean;
  }
}

// Finite visibility in [0, 1] and finite views everywhere, on every built-in and stress scene.
TEST(Pcss, VisibilityIsFiniteAndInRangeOnEveryScene) {
  std::vector<std::string> names = builtinSceneNames();
  for (const std::string& stress : stressSceneNames()) names.push_back(stress);
  for (const std::string& name : names) {
    PipelineRun run(isStressScene(name) ? makeStressScene(name) : makeBuiltinScene(name), {}, 96, 96);
    int shadowed = 0;
    for (float v : run.read("pcss.visibility")) {
      ASSERT_TRUE(std::isfinite(v) && v >= 0.0f && v <= 1.0f) << name << ": " << v;
      shadowed += v < 1.0f;
    }
    for (const char* view : {"pcss.searchRadius", "pcss.blockerDepth", "pcss.filterRadius"})
      for (float v : run.read(view)) ASSERT_TRUE(std::isfinite(v) && v >= 0.0f) << name << " " << view;
    std::printf("%-22s %5d shadowed pixels\n", name.c_str(), shadowed);
  }
}

// The cube in the default settings (those of `penumbra export --scene cube`): each face of
// the box turned towards the light centre has nothing in front of its plane (the box lies
// behind it, the ground below), so no blocker exists and PCSS must leave it lit. Compared
// with the receiver's own depth, the face's texels up its slope were "blockers" and the
// filter region collapsed onto the receiver's texel: visibility 0 or 1 pixel by pixel (acne).
// The reference is below 1 on the front faces (0.725): the part of the light behind the
// face's own plane, a horizon, which no shadow map models (docs/ssm_pcss.md).
TEST(Pcss, CubeFacesTurnedToTheLightAreLit) {
  PipelineRun run(makeBuiltinScene("cube"), {}, 256, 256);
  const glm::vec3 wsLight = run.scene.light.center;
  const auto wsPosition = run.read("gbuffer.wsPosition");
  const auto wsNormal = run.read("gbuffer.wsNormal");
  const auto visibility = run.read("pcss.visibility");
  int faced = 0, top = 0, dark = 0;
  double smallest = 1;
  for (size_t i = 0; i < visibility.size(); ++i) {
    const glm::vec3 p(wsPosition[4 * i], wsPosition[4 * i + 1], wsPosition[4 * i + 2]);
    const glm::vec3 n(wsNormal[4 * i], wsNormal[4 * i + 1], wsNormal[4 * i + 2]);
    if (wsPosition[4 * i + 3] <= 0 || p.y < 0.5f) continue;  // the box (0.65 <= y <= 1.15)
    if (glm::dot(n, glm::normalize(wsLight - p)) < 0.05f) continue;
    ++faced;
    top += n.y > 0.99f;
    if (visibility[i] < 0.99f) ++dark;
    smallest = std::min(smallest, double(visibility[i]));
  }
  std::printf("cube: %d box pixels facing the light (%d on the top face), %d below 0.99 "
              "(smallest %.3f)\n", faced, top, dark, smallest);
  EXPECT_GT(top, 1000);
  EXPECT_GT(faced - top, 2000);  // the front face
  EXPECT_LE(dark, faced / 100);
}
