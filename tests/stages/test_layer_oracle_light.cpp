// Self-tests of the layer oracle's light-space side: light samples and receivers mapped to
// texel space (against lightClipFromWorld), the perspective ray model (1/z affine in s), the
// bias, dense visibility against an analytic half-plane occluder, and the third layer. No GL.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "support/layer_oracle.h"
#include "support/layer_oracle_fields.h"

namespace {
constexpr int kMapW = 64, kMapH = 48;  // not square, so a swapped axis shows

// Texel position and w of a world point through the matrix the shaders use.
glm::vec3 projectWithClipMatrix(const LightFrame& frame, const glm::vec3& ws) {
  const glm::vec4 clip = frame.lightClipFromWorld * glm::vec4(ws, 1);
  const glm::vec2 uv = glm::vec2(clip) / clip.w * 0.5f + 0.5f;
  return {uv * glm::vec2(kMapW, kMapH), clip.w};
}

struct RandomSetup {
  AreaLight light;
  LightFrame frame;
};
RandomSetup randomSetup(std::mt19937& random) {
  std::uniform_real_distribution<float> unit(-1, 1);
  RandomSetup setup;
  AreaLight& light = setup.light;
  light.center = {unit(random) * 3, 4 + unit(random), unit(random) * 3};
  light.forward = glm::normalize(glm::vec3(unit(random) * 0.5f, -1, unit(random) * 0.5f));
  light.up = glm::normalize(glm::vec3(unit(random), 0.2f, unit(random) + 2));
  light.width = 0.1f + 2 * std::fabs(unit(random));
  light.height = 0.1f + 2 * std::fabs(unit(random));
  Bounds bounds;
  bounds.extend({-5, -1, -5});
  bounds.extend({5, 3, 5});
  setup.frame = computeLightFrame(light, bounds, 60 + 60 * std::fabs(unit(random)));
  return setup;
}
glm::vec3 randomReceiver(std::mt19937& random) {
  std::uniform_real_distribution<float> unit(-1, 1);
  return {unit(random) * 3, unit(random), unit(random) * 3};
}
}  // namespace

TEST(LayerOracleLight, LightSamplesLandOnTheirTexelsAtTheNearPlane) {
  std::mt19937 random(11);
  std::uniform_real_distribution<float> unit01(0, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const RandomSetup setup = randomSetup(random);
    const glm::vec2 sample(unit01(random), unit01(random));
    const glm::vec3 wsLight(lightSampleWorld(setup.frame, setup.light, sample));
    const glm::vec3 projected = projectWithClipMatrix(setup.frame, wsLight);
    const glm::vec2 expected = sample * glm::vec2(kMapW, kMapH);
    EXPECT_NEAR(projected.x, expected.x, 2e-3f);
    EXPECT_NEAR(projected.y, expected.y, 2e-3f);
    EXPECT_NEAR(projected.z, setup.frame.zNear, 1e-5f * setup.frame.zNear);
    const OracleRay ray = makeRay(setup.frame, setup.light, kMapW, kMapH, sample, randomReceiver(random), 0);
    EXPECT_EQ(ray.texelA, expected);
    EXPECT_EQ(ray.zA, setup.frame.zNear);
    // The double-precision mapping agrees with the clip matrix and inverts.
    const glm::dvec3 map = lightMapFromWorld(setup.frame, kMapW, kMapH, glm::dvec3(wsLight));
    EXPECT_NEAR(map.x, expected.x, 2e-3);
    EXPECT_NEAR(map.y, expected.y, 2e-3);
    const glm::dvec3 back = worldFromLightMap(setup.frame, kMapW, kMapH, glm::dvec2(map), map.z);
    EXPECT_LT(glm::distance(back, glm::dvec3(wsLight)), 1e-9);
  }
}

TEST(LayerOracleLight, ReceiverEndIsBiasedTowardsTheLightAndDepthIsPerspective) {
  std::mt19937 random(12);
  std::uniform_real_distribution<float> unit01(0, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const RandomSetup setup = randomSetup(random);
    const LightFrame& frame = setup.frame;
    const glm::vec2 sample(unit01(random), unit01(random));
    const glm::vec3 receiver = randomReceiver(random);
    const glm::dvec3 wsLight = lightSampleWorld(frame, setup.light, sample);
    // No bias: B is the receiver's projection.
    const OracleRay unbiased = makeRay(frame, setup.light, kMapW, kMapH, sample, receiver, 0);
    const glm::vec3 projected = projectWithClipMatrix(frame, receiver);
    EXPECT_NEAR(unbiased.texelB.x, projected.x, 2e-3f);
    EXPECT_NEAR(unbiased.texelB.y, projected.y, 2e-3f);
    EXPECT_NEAR(unbiased.zB, projected.z, 1e-5f * projected.z);
    // Bias: B is `bias` world units from the receiver, towards the light sample.
    const float bias = 0.05f + 0.2f * unit01(random);
    const OracleRay ray = makeRay(frame, setup.light, kMapW, kMapH, sample, receiver, bias);
    const glm::dvec3 wsEnd = worldFromLightMap(frame, kMapW, kMapH, glm::dvec2(ray.texelB), ray.zB);
    const double length = glm::distance(wsLight, glm::dvec3(receiver));
    EXPECT_NEAR(glm::distance(wsEnd, glm::dvec3(receiver)), bias, 1e-4);
    EXPECT_NEAR(glm::distance(wsEnd, wsLight), length - bias, 1e-4);
    // Perspective: points of the world segment light -> end project onto P(s) with
    // 1/z(s) = (1 - s)/zA + s/zB, and the oracle maps P(s), z(s) back to them.
    const RayDepth depth(ray, frame.zNear, frame.zFar);
    const glm::dvec2 a(ray.texelA), ab = glm::dvec2(ray.texelB) - a;
    for (double t : {0.1, 0.37, 0.5, 0.8, 0.99}) {
      const glm::dvec3 ws = wsLight + t * (wsEnd - wsLight);
      const glm::dvec3 map = lightMapFromWorld(frame, kMapW, kMapH, ws);
      const double s = glm::dot(glm::dvec2(map) - a, ab) / glm::dot(ab, ab);
      EXPECT_LT(glm::length(glm::dvec2(map) - rayPoint(ray, s)), 2e-3) << "not on the segment";
      if (glm::length(ab) < 1) continue;  // s is ill-conditioned along the light's line of sight
      EXPECT_NEAR(depth.zAt(s), map.z, 1e-4 * map.z);
      EXPECT_LT(glm::distance(worldFromLightMap(frame, kMapW, kMapH, rayPoint(ray, s), depth.zAt(s)), ws), 2e-3);
    }
    // A bias longer than the ray stops at the light sample: B == A.
    const OracleRay swallowed = makeRay(frame, setup.light, kMapW, kMapH, sample, receiver, float(length) + 1);
    EXPECT_EQ(swallowed.texelB, swallowed.texelA);
    EXPECT_EQ(swallowed.zB, swallowed.zA);
  }
}

// Light 2 x 2 at height 4 facing down, fov 90: projection point at height 5 (Eq 3.1). A plate
// at height 2 (z = 3) covers world x < 0, which is map columns < W/2 exactly. A ray from the
// light point x = lx to a ground receiver x = rx crosses the plate's height at (lx + rx)/2, so
// the sample is blocked iff lx < -rx: visibility is a count of grid columns, known exactly.
TEST(LayerOracleLight, DenseVisibilityMatchesAHalfPlaneOccluderExactly) {
  AreaLight light{{0, 4, 0}, {0, -1, 0}, {0, 0, -1}, 2, 2};
  Bounds bounds;
  bounds.extend({-6, 0, -6});
  bounds.extend({6, 4, 6});
  const LightFrame frame = computeLightFrame(light, bounds, 90);
  ASSERT_NEAR(frame.zNear, 1.0f, 1e-6f);
  const int w = 128, h = 128, n = 16;
  LayerMaps maps = emptyLayers(w, h);
  const float plateDepth = float((3.0 - frame.zNear) / (frame.zFar - frame.zNear));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w / 2; ++x) maps.nearLayer[y * w + x] = maps.farLayer[y * w + x] = plateDepth;
  ASSERT_NEAR(worldFromLightMap(frame, w, h, {w / 2.0, 10}, 3.0).x, 0.0, 1e-6);  // the edge is x = 0
  for (float rx : {-1.3f, -0.61f, -0.2f, 0.07f, 0.55f, 0.93f, 1.4f}) {
    int visible = 0;
    for (int i = 0; i < n; ++i) visible += -1.0f + 2.0f * (i + 0.5f) / n >= -rx;
    const float expected = float(visible) / n;
    const glm::vec3 receiver(rx, 0, 0.3f);
    EXPECT_EQ(denseVisibility(maps, frame, light, receiver, 0.01f, n, 2), expected) << "rx " << rx;
    // One layer (§3.2): a receiver under the plate is behind its near layer on every ray.
    EXPECT_EQ(denseVisibility(maps, frame, light, receiver, 0.01f, n, 1), rx < 0 ? 0.0f : expected);
  }
}

TEST(LayerOracleLight, ThirdLayerRemovesWhatTheEyeSees) {
  std::mt19937 random(13);
  std::uniform_real_distribution<float> unit01(0, 1);
  int rays = 0, twoLayerHits = 0, neverSeenHits = 0, partialAgree = 0, partialHits = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    const RandomSetup setup = randomSetup(random);
    const LayerMaps maps = randomLayers(40, 30, uint32_t(trial));
    const OracleRay ray = makeRay(setup.frame, setup.light, maps.width, maps.height,
                                  {unit01(random), unit01(random)}, randomReceiver(random), 0.01f);
    const glm::dvec3 wsLight = worldFromLightMap(setup.frame, maps.width, maps.height, glm::dvec2(ray.texelA), ray.zA);
    const glm::dvec3 wsEnd = worldFromLightMap(setup.frame, maps.width, maps.height, glm::dvec2(ray.texelB), ray.zB);
    const glm::dvec3 axis = glm::normalize(wsEnd - wsLight);
    // Every point handed to the eye test lies on the world ray.
    auto onRay = [&](const glm::dvec3& ws) {
      const glm::dvec3 v = ws - wsLight;
      EXPECT_LT(glm::length(v - glm::dot(v, axis) * axis), 1e-3);
    };
    const OracleHit two = traceTwoLayers(maps, ray, setup.frame.zNear, setup.frame.zFar);
    const OracleHit never = traceThreeLayers(maps, ray, setup.frame, [&](const glm::dvec3& ws) {
      onRay(ws);
      return false;
    });
    const OracleHit always = traceThreeLayers(maps, ray, setup.frame, [](const glm::dvec3&) { return true; });
    // Seen from the eye everywhere: nothing occludes. Seen nowhere: exactly two layers.
    EXPECT_FALSE(always.occluded);
    ASSERT_EQ(never.occluded, two.occluded) << "trial " << trial;
    if (two.occluded) {
      EXPECT_EQ(never.s, two.s);
      EXPECT_EQ(never.texel, two.texel);
      EXPECT_EQ(never.texelsVisited, two.texelsVisited);
    }
    ++rays;
    twoLayerHits += two.occluded;
    neverSeenHits += never.occluded;
    // A half-space the eye sees: compare with brute-force sampling of s.
    auto seen = [](const glm::dvec3& ws) { return ws.x + 0.5 * ws.z > 0.2; };
    const OracleHit partial = traceThreeLayers(maps, ray, setup.frame, seen);
    const RayDepth depth(ray, setup.frame.zNear, setup.frame.zFar);
    bool brute = false;
    for (int i = 0; i <= 4000 && !brute; ++i) {
      const double s = i / 4000.0;
      const glm::ivec2 t(glm::floor(rayPoint(ray, s)));
      if (!maps.contains(t) || depth.at(s) < maps.nearAt(t) || depth.at(s) > maps.farAt(t)) continue;
      brute = !seen(worldFromLightMap(setup.frame, maps.width, maps.height, rayPoint(ray, s), depth.zAt(s)));
    }
    partialAgree += partial.occluded == brute;
    partialHits += partial.occluded;
  }
  std::printf("third layer: %d rays, two layers %d hits, eye-never-sees %d hits, half-space %d "
              "hits, %.2f%% agree with 4001 samples\n",
              rays, twoLayerHits, neverSeenHits, partialHits, 100.0 * partialAgree / rays);
  EXPECT_GE(partialAgree, rays * 97 / 100);
  EXPECT_GT(partialHits, 0);
  EXPECT_LT(partialHits, neverSeenHits);
}
