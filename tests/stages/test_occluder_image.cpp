// The occluders' images in the light's map (stages/shared_inputs/light/occluder_image.h), which
// `auto` reads for the map of a steep occluder. Oracles: the minimum width by brute force
// (every line through two of the points that has them all on one side: the widest point
// from it), and the analytic image of a quad seen from the projection point.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <random>
#include <vector>

#include "scene/light_frame.h"
#include "scene/mesh_builders.h"
#include "shared_inputs/light/occluder_image.h"
#include "support/analytic_scenes.h"

namespace {

// The minimum over supporting lines through two of the points of the farthest point's
// distance: the width of the point set (a minimum-width strip has a hull edge on one side).
double bruteMinimumWidth(const std::vector<glm::dvec2>& points) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < points.size(); ++i)
    for (size_t j = 0; j < points.size(); ++j) {
      const glm::dvec2 edge = points[j] - points[i];
      const double length = glm::length(edge);
      if (length < 1e-12) continue;
      double low = 0, high = 0;
      for (const glm::dvec2& p : points) {
        const double side = (edge.x * (p.y - points[i].y) - edge.y * (p.x - points[i].x)) / length;
        low = std::min(low, side);
        high = std::max(high, side);
      }
      if (low > -1e-12 || high < 1e-12) best = std::min(best, high - low);
    }
  return best;
}

TEST(OccluderImage, MinimumWidthMatchesBruteForce) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (int trial = 0; trial < 200; ++trial) {
    // Points in a turned, stretched box (some repeated, some inside), then a few outliers.
    const double angle = 3.14159 * unit(random), stretch = 0.01 + 0.5 * (1 + unit(random));
    const glm::dvec2 along(std::cos(angle), std::sin(angle)), across(-along.y, along.x);
    std::vector<glm::dvec2> points;
    const int count = 3 + trial % 90;
    for (int k = 0; k < count; ++k)
      points.push_back(unit(random) * along + stretch * unit(random) * across);
    if (trial % 3 == 0) points.push_back(points.front());
    const double expected = bruteMinimumWidth(points);
    EXPECT_NEAR(convexHullMinimumWidth(points), expected, 1e-9 * (1 + expected))
        << "trial " << trial;
  }
  // Collinear points and a single point have no width.
  EXPECT_EQ(convexHullMinimumWidth({{0, 0}, {1, 1}, {2, 2}, {3, 3}}), 0.0);
  EXPECT_EQ(convexHullMinimumWidth({{1, 2}}), 0.0);
  // A square of side 2 turned 30 degrees: 2; many points inside do not change it.
  std::vector<glm::dvec2> square;
  const double c = std::cos(0.5236), s = std::sin(0.5236);
  for (int k = 0; k < 4000; ++k) {
    const double x = (k % 4 < 2 ? -1 : 1) * (k < 4 ? 1.0 : 0.9 * (k % 97) / 97.0);
    const double y = (k % 2 ? -1 : 1) * (k < 4 ? 1.0 : 0.9 * (k % 89) / 89.0);
    square.push_back({c * x - s * y, s * x + c * y});
  }
  EXPECT_NEAR(convexHullMinimumWidth(square), 2.0, 1e-9);
}

// A unit sheet `degrees` from edge-on under the suite's light (as the hard cases build it):
// its image is about sin(degrees) / depth across, and it is steep; a rod lying across the
// light's rays, and a plate facing the light, are not.
TEST(OccluderImage, SheetNearlyEdgeOnIsNarrowAndSteep) {
  for (float degrees : {1.0f, 4.0f, 12.0f}) {
    Scene scene = makeAnalyticScene("plate_mid");
    scene.objects.resize(1);
    const glm::mat4 sheet = glm::rotate(glm::translate(glm::mat4(1), {0, 1, 0}),
                                        glm::radians(90.0f - degrees), glm::vec3(0, 0, 1));
    const glm::mat4 rod = glm::translate(glm::mat4(1), {0, 1.5f, 0});
    const glm::mat4 plate = glm::translate(glm::mat4(1), {0, 0.5f, 0});
    scene.objects.push_back({"sheet", makeQuad(1.0f, sheet), {1, 1, 1}, false});
    scene.objects.push_back({"rod", makeBox({1.0f, 0.02f, 0.02f}, rod), {1, 1, 1}, false});
    scene.objects.push_back({"plate", makeQuad(0.5f, plate), {1, 1, 1}, false});
    const LightFrame light = computeLightFrame(scene.light, scene.bounds(), 90.0f);
    const std::vector<OccluderImage> images = occluderImages(scene, light);
    ASSERT_EQ(images.size(), 4u);
    EXPECT_TRUE(std::isinf(images[0].width)) << "the receiver-only ground has no image";
    // The sheet's two long edges, from the projection point: their directions differ by
    // about sin(degrees) / distance; on the map's plane at unit depth that is the width.
    const glm::vec3 p = light.wsProjectionPoint;
    const float depth = glm::dot(glm::vec3(0, 1, 0) - p, light.forward);
    const double expected =
        std::sin(glm::radians(double(degrees))) / depth / (2.0 * light.tanHalfFovX);
    EXPECT_NEAR(images[1].width, expected, 0.35 * expected) << degrees << " degrees";
    EXPECT_GT(images[1].depthOverWidth, 2.0) << degrees << " degrees: steep";
    EXPECT_LT(images[2].depthOverWidth, 2.0) << "the rod lies across the rays";
    EXPECT_LT(images[3].depthOverWidth, 0.01) << "the plate faces the light";
    EXPECT_GT(images[3].width, images[2].width);
  }
}

}  // namespace
