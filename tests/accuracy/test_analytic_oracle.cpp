// The analytic oracle (tests/support/analytic_visibility.h) checked on its own: union areas
// with known answers, the closed form of parallel squares, and dense ray casting on every
// scene of the accuracy suite.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "support/analytic_scenes.h"
#include "support/analytic_visibility.h"

namespace {

std::vector<glm::dvec2> square(double x0, double y0, double side) {
  return {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
}

TEST(AnalyticOracle, UnionAreaOfKnownShapes) {
  EXPECT_NEAR(unionArea({square(0, 0, 1)}), 1.0, 1e-15);
  EXPECT_NEAR(unionArea({square(0, 0, 1), square(0.5, 0.5, 1)}), 1.75, 1e-12);
  EXPECT_NEAR(unionArea({square(0, 0, 1), square(2, 2, 1)}), 2.0, 1e-12);
  EXPECT_NEAR(unionArea({square(0, 0, 1), square(0.25, 0.25, 0.5)}), 1.0, 1e-12);
  // A square and the same square rotated 45 degrees about its centre: a regular octagon
  // of circumradius... area = 8 * (1/2) r^2 sin 45 with r the octagon's vertex distance;
  // known value: union = 2 - area(octagon) with octagon = 2 (sqrt 2 - 1) for side 1.
  const double c = 0.5, r = std::sqrt(0.5);
  std::vector<glm::dvec2> diamond;
  for (int k = 0; k < 4; ++k)
    diamond.push_back({c + r * std::cos(k * M_PI / 2), c + r * std::sin(k * M_PI / 2)});
  EXPECT_NEAR(unionArea({square(0, 0, 1), diamond}), 2.0 - 2.0 * (std::sqrt(2.0) - 1.0), 1e-12);
  // Two triangles of one quad (a shared diagonal) cover the quad once.
  EXPECT_NEAR(unionArea({{{0, 0}, {1, 0}, {1, 1}}, {{0, 0}, {1, 1}, {0, 1}}}), 1.0, 1e-12);
}

TEST(AnalyticOracle, ParallelSquaresMatchTheClosedForm) {
  // Light [-0.5, 0.5]^2 at y = 3, plate [-0.5, 0.5]^2 at y = 1, ground points (y = 0): the
  // plate's shadow is the square scaled by 3 about p (test_reference.cpp's formula).
  const Scene scene = makeAnalyticScene("plate_mid");
  const AnalyticLight light = analyticLight(scene.light);
  const auto occluders = occluderTriangles(scene);
  for (double x : {-1.3, -0.9, -0.5, 0.0, 0.2, 0.61, 1.0})
    for (double z : {-1.1, -0.4, 0.0, 0.33, 0.8}) {
      double covered = 1;
      for (double o : {x, z}) {
        const double lo = std::clamp(o + 3 * (-0.5 - o) + 0.5, 0.0, 1.0);
        const double hi = std::clamp(o + 3 * (0.5 - o) + 0.5, 0.0, 1.0);
        covered *= hi - lo;
      }
      EXPECT_NEAR(analyticVisibility(light, occluders, {x, 0, z}, {0, 1, 0}), 1 - covered, 1e-12)
          << x << ", " << z;
    }
}

// Dense ray casting (400 x 400 cell centres) agrees within the quadrature's error on random
// receivers of every suite scene, including tilted receivers that see part of the light
// behind their tangent plane.
TEST(AnalyticOracle, AgreesWithDenseRayCasting) {
  std::mt19937 random(12);
  std::uniform_real_distribution<double> unit(0, 1);
  for (const std::string& name : analyticSceneNames()) {
    const Scene scene = makeAnalyticScene(name);
    const AnalyticLight light = analyticLight(scene.light);
    const auto occluders = occluderTriangles(scene);
    int partial = 0;
    for (int k = 0; k < 60; ++k) {
      // Half anywhere, half within 0.02 of the shadow of a plate's edge on the ground (x =
      // +-0.51 for the contact plates, +-0.75 for those at y = 1), where the narrow penumbrae
      // (contact, tiny light) lie.
      glm::dvec3 p{-2 + 4 * unit(random), k % 3 == 0 ? 0.3 * unit(random) : 0.0,
                   -2 + 4 * unit(random)};
      if (k % 2) p = {std::array{-0.75, -0.51, 0.51, 0.75}[(k / 2) % 4] + 0.04 * (unit(random) - 0.5), 0, 0.8 * unit(random) - 0.4};
      glm::dvec3 n{0, 1, 0};
      if (k % 4 == 1) n = glm::normalize(glm::dvec3(unit(random) - 0.5, 0.4, unit(random) - 0.5));
      const double exact = analyticVisibility(light, occluders, p, n);
      const double dense = rayCastVisibility(light, occluders, p, n, 400);
      // Cell-centre quadrature: error below (perimeter of the shadow in cells) / m^2.
      EXPECT_NEAR(exact, dense, 0.006) << name << " at " << p.x << ", " << p.y << ", " << p.z;
      partial += exact > 0.02 && exact < 0.98;
    }
    EXPECT_GT(partial, 3) << name << ": the random receivers should meet the penumbra";
  }
}

}  // namespace
