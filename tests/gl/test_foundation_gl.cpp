// The foundation on llvmpipe: context, light layers, G-buffer, hard shadows, export.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>

#include "io/image_export.h"
#include "scene/mesh_builders.h"
#include "scene/scene_builtin.h"
#include "support/gl_test.h"
#include "support/temp_directory.h"

TEST(GlContextTest, HeadlessContextIsGl45Core) {
  GlContext& context = headlessContext();
  EXPECT_GE(context.majorVersion() * 10 + context.minorVersion(), 45) << context.renderer();
  EXPECT_TRUE(context.isCoreProfile());
}

TEST(LightLayers, NearBeforeFarWhereCoveredClearedElsewhere) {
  PipelineRun run(makeBuiltinScene("cube"), {"light.resolution=256"});
  const auto nearLayer = run.read("light_layers.near");
  const auto farLayer = run.read("light_layers.far");
  int covered = 0, empty = 0;
  for (size_t i = 0; i < nearLayer.size(); ++i) {
    const bool nearEmpty = nearLayer[i] == 1.0f, farEmpty = farLayer[i] == 0.0f;
    EXPECT_EQ(nearEmpty, farEmpty) << "texel " << i;  // one occluder covers both or neither
    if (nearEmpty) { ++empty; continue; }
    ++covered;
    EXPECT_LE(nearLayer[i], farLayer[i]) << "texel " << i;
  }
  EXPECT_GT(covered, 500);  // the cube is there...
  EXPECT_GT(empty, 500);    // ...and the ground (receiver only) is not
}

TEST(LightLayers, ReceiverOnlyObjectsAreAbsentFromBothLayers) {
  Scene scene = makeBuiltinScene("cube");
  for (SceneObject& object : scene.objects) object.receiverOnly = true;
  PipelineRun run(scene, {"light.resolution=128"});
  for (float value : run.read("light_layers.near")) ASSERT_EQ(value, 1.0f);
  for (float value : run.read("light_layers.far")) ASSERT_EQ(value, 0.0f);
}

TEST(GBuffer, WorldPositionEqualsPositionReconstructedFromEyeDepth) {
  PipelineRun run(makeBuiltinScene("spheres"), {}, 200, 150);
  const auto positions = run.read("gbuffer.wsPosition");
  const auto depth = run.read("gbuffer.depth");
  const glm::mat4 worldFromClip = run.frame->uniforms.worldFromClip;
  int checked = 0;
  double worst = 0;
  for (int y = 0; y < 150; ++y)
    for (int x = 0; x < 200; ++x) {
      const size_t i = size_t(y) * 200 + x;
      if (positions[i * 4 + 3] == 0) continue;
      // Window -> NDC (default depth range [0,1] -> [-1,1]) -> world.
      const glm::vec4 ndc{(x + 0.5f) / 200 * 2 - 1, (y + 0.5f) / 150 * 2 - 1, depth[i] * 2 - 1, 1};
      const glm::vec4 world = worldFromClip * ndc;
      const glm::vec3 reconstructed = glm::vec3(world) / world.w;
      const glm::vec3 stored{positions[i * 4], positions[i * 4 + 1], positions[i * 4 + 2]};
      const double error = glm::distance(reconstructed, stored);
      worst = std::max(worst, error);
      ++checked;
    }
  EXPECT_GT(checked, 10000);
  EXPECT_LT(worst, 2e-3) << "largest world-space distance over " << checked << " pixels";
}

// With a point-sized light, the plate's hard shadow on the ground is the plate's central
// projection from the light center: a square of side 1 * 3 / (3 - 1) = 1.5.
TEST(HardShadow, PlateShadowEqualsAnalyticProjectionWithinOneTexel) {
  Scene scene = makeBuiltinScene("plate");
  scene.light.width = scene.light.height = 1e-3f;
  const int mapSize = 512;
  PipelineRun run(scene, {"light.resolution=" + std::to_string(mapSize)}, 320, 320);
  const auto positions = run.read("gbuffer.wsPosition");
  const auto visibility = run.read("hard_shadow.visibility");
  // One shadow-map texel on the ground: the map spans 2 * depth * tan(fov/2) there.
  const float texelOnGround = 2 * 3.0f * run.frame->light.tanHalfFovX / mapSize;
  int groundPixels = 0, shadowed = 0, mismatches = 0, mismatchesAwayFromBorder = 0;
  for (size_t i = 0; i < visibility.size(); ++i) {
    const glm::vec3 p{positions[i * 4], positions[i * 4 + 1], positions[i * 4 + 2]};
    if (positions[i * 4 + 3] == 0 || std::fabs(p.y) > 1e-3f) continue;  // ground only
    ++groundPixels;
    const float borderDistance = std::max(std::fabs(p.x), std::fabs(p.z)) - 0.75f;
    const bool analyticShadow = borderDistance < 0;
    const bool stageShadow = visibility[i] < 0.5f;
    shadowed += stageShadow;
    if (analyticShadow != stageShadow) {
      ++mismatches;
      if (std::fabs(borderDistance) > texelOnGround) ++mismatchesAwayFromBorder;
    }
  }
  EXPECT_GT(groundPixels, 20000);
  EXPECT_GT(shadowed, 1000);
  EXPECT_EQ(mismatchesAwayFromBorder, 0) << mismatches << " mismatches in total";
}

TEST(Export, ExrReadBackEqualsGpuBufferBitForBit) {
  PipelineRun run(makeBuiltinScene("cube"), {"light.resolution=128"}, 96, 64);
  const TempDirectory scratch("penumbra_exr_test");
  const std::filesystem::path& directory = scratch.path();
  for (const std::string key : {"gbuffer.wsPosition", "light_layers.near", "hard_shadow.visibility"}) {
    const size_t dot = key.find('.');
    const Output& output = run.pipeline->stage(key.substr(0, dot)).output(key.substr(dot + 1));
    const GlTexture& texture = run.frame->texture(key);
    exportTexture(directory, key, texture, output);
    int width = 0, height = 0;
    std::vector<std::string> channels;
    const auto readBack = readExr(directory / (key + ".exr"), width, height, channels);
    const auto gpu = texture.readFloats();
    ASSERT_EQ(width, texture.width());
    ASSERT_EQ(height, texture.height());
    EXPECT_EQ(channels, output.channels);
    ASSERT_EQ(readBack.size(), gpu.size());
    EXPECT_EQ(std::memcmp(readBack.data(), gpu.data(), gpu.size() * sizeof(float)), 0) << key;
    EXPECT_TRUE(std::filesystem::exists(directory / (key + ".png")));
    EXPECT_FALSE(std::filesystem::exists(directory / (key + ".partial.exr")));
  }
}
