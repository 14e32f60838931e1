// Eq 3.1 and the light frustum: property tests, no GL needed.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "scene/light_frame.h"

namespace {
glm::vec3 project(const glm::mat4& clipFromWorld, const glm::vec3& p, float& w) {
  const glm::vec4 clip = clipFromWorld * glm::vec4(p, 1);
  w = clip.w;
  return glm::vec3(clip) / clip.w;
}
}  // namespace

TEST(LightFrame, Eq31LightDepthMatchesTheFrustumGeometry) {
  // The light's half side seen from the projection point spans exactly fov/2.
  for (float fov : {30.0f, 60.0f, 90.0f, 120.0f})
    for (float size : {0.001f, 0.5f, 2.0f, 10.0f}) {
      const float depth = lightDepthEq31(size, glm::radians(fov));
      EXPECT_NEAR(std::atan2(size / 2, depth) * 2, glm::radians(fov), 1e-5f);
    }
}

TEST(LightFrame, ProjectionPointSitsBehindTheCenterAtLightDepth) {
  AreaLight light{{1, 5, -2}, glm::normalize(glm::vec3(0.3f, -1, 0.2f)), {0, 0, 1}, 2.0f, 1.0f};
  Bounds bounds;
  bounds.extend({-3, 0, -3});
  bounds.extend({3, 2, 3});
  const LightFrame frame = computeLightFrame(light, bounds, 90);
  EXPECT_NEAR(glm::distance(frame.wsProjectionPoint, light.center), frame.lightDepth, 1e-5f);
  EXPECT_NEAR(frame.lightDepth, lightDepthEq31(2.0f, glm::radians(90.0f)), 1e-6f);
  EXPECT_GT(glm::dot(light.center - frame.wsProjectionPoint, light.forward), 0);
}

TEST(LightFrame, WholeLightRectangleProjectsInsideTheFrustum) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(-1, 1);
  for (int trial = 0; trial < 50; ++trial) {
    AreaLight light;
    light.center = {unit(random) * 3, 4 + unit(random), unit(random) * 3};
    light.forward = glm::normalize(glm::vec3(unit(random) * 0.5f, -1, unit(random) * 0.5f));
    light.up = glm::normalize(glm::vec3(unit(random), 0.2f, unit(random) + 2));
    light.width = 0.1f + 2 * std::fabs(unit(random));
    light.height = 0.1f + 2 * std::fabs(unit(random));
    Bounds bounds;
    bounds.extend({-5, -1, -5});
    bounds.extend({5, 3, 5});
    const LightFrame frame = computeLightFrame(light, bounds, 60 + 60 * std::fabs(unit(random)));
    const glm::vec3 right = frame.right * light.width * 0.5f, up = frame.up * light.height * 0.5f;
    float maxCorner = 0;
    for (float a : {-1.0f, 1.0f})
      for (float b : {-1.0f, 1.0f}) {
        float w;
        const glm::vec3 ndc = project(frame.lightClipFromWorld, light.center + a * right + b * up, w);
        maxCorner = std::max({maxCorner, std::fabs(ndc.x), std::fabs(ndc.y)});
        EXPECT_NEAR(w, frame.zNear, 1e-4f * frame.zNear + 1e-5f);  // on the near plane
      }
    // The rectangle fills the frustum's cross-section: corners land on the map's corners.
    EXPECT_NEAR(maxCorner, 1.0f, 1e-4f);
    // Interior points are strictly inside.
    for (int i = 0; i < 20; ++i) {
      float w;
      const glm::vec3 ndc = project(frame.lightClipFromWorld,
                                    light.center + unit(random) * 0.999f * right +
                                        unit(random) * 0.999f * up, w);
      EXPECT_LT(std::fabs(ndc.x), 1.0f);
      EXPECT_LT(std::fabs(ndc.y), 1.0f);
    }
    // The far plane lies beyond every scene point.
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 p{corner & 1 ? 5.f : -5.f, corner & 2 ? 3.f : -1.f, corner & 4 ? 5.f : -5.f};
      EXPECT_LT(glm::dot(p - frame.wsProjectionPoint, frame.forward), frame.zFar);
    }
  }
}
