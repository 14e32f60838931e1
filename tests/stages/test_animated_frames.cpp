// Time through the pipeline: a frame of an animated scene at time t is, bit for bit, the
// frame of the static scene written with every object and the light where the animation
// puts them at t, for every method (Monte Carlo, SSM, PCSS, hard shadows, 4D rasterization,
// the Embree reference), after the same pipeline has run the scene at another time: no
// stage keeps anything across time. The reference's caches: its image cache is keyed on the
// posed geometry (invalidated when an object moves), its BVH is rebuilt when an occluder
// moved and reused when only the camera did.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <string>

#include "scene/animation.h"
#include "scene/scene_file.h"
#include "support/gl_test.h"
#include "support/temp_directory.h"

namespace {

// A square 1 across (two triangles, normal +y), written as a glTF.
std::string writeSquare(const TempDirectory& dir) {
  std::string bin;
  for (float v : {-0.5f, 0.f, -0.5f, 0.5f, 0.f, -0.5f, 0.5f, 0.f, 0.5f, -0.5f, 0.f, 0.5f})
    bin.append(reinterpret_cast<const char*>(&v), 4);
  for (std::uint16_t i : {0, 3, 2, 0, 2, 1}) bin.append(reinterpret_cast<const char*>(&i), 2);
  dir.write("square.bin", bin);
  return dir.write("square.gltf", R"({"asset": {"version": "2.0"}, "scene": 0,
    "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
    "accessors": [
      {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
       "min": [-0.5, 0, -0.5], "max": [0.5, 0, 0.5]},
      {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}],
    "bufferViews": [{"buffer": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 12}],
    "buffers": [{"uri": "square.bin", "byteLength": 60}]})");
}

// Values with few binary digits, so the pose at t = 1 (halfway along each track) is exact
// in float: the square at x 0.5 (from 0 to 1 over 2 s), the light at x 0.25 and 1.5 wide.
const char* kAnimated = R"({"objects": [
    {"ground": {"size": 8}},
    {"gltf": "square.gltf", "translate": [0, 1, 0], "color": [0.5, 0.5, 0.5],
     "animation": {"translate": {"times": [0, 2], "values": [[0, 0, 0], [1, 0, 0]]}}}],
  "light": {"center": [0, 4, 0], "forward": [0, -1, 0], "up": [0, 0, -1], "width": 1, "height": 1,
            "animation": {"center": {"times": [0, 2], "values": [[0, 4, 0], [0.5, 4, 0]]},
                          "width": {"times": [0, 2], "values": [1, 2]}}},
  "camera": {"position": [0, 3, 6], "target": [0, 0, 0]}})";

const char* kStaticAtOne = R"({"objects": [
    {"ground": {"size": 8}},
    {"gltf": "square.gltf", "translate": [0.5, 1, 0], "color": [0.5, 0.5, 0.5]}],
  "light": {"center": [0.25, 4, 0], "forward": [0, -1, 0], "up": [0, 0, -1], "width": 1.5,
            "height": 1},
  "camera": {"position": [0, 3, 6], "target": [0, 0, 0]}})";

const std::vector<std::string> kEveryMethod = {
    "raster4d.enabled=true", "raster4d.samples=8", "reference.enabled=true",
    "reference.cache=false", "reference.samples=8"};

// The pipeline's frame moved to `scene` (the window's adoptScene does the same).
void moveTo(PipelineRun& run, Scene scene) {
  run.scene = std::move(scene);
  const int width = run.frame->eyeWidth, height = run.frame->eyeHeight;
  run.gpuScene = std::make_unique<GpuScene>(run.scene);
  run.frame = std::make_unique<Frame>(run.scene, *run.gpuScene, *run.pipeline);
  run.frame->eyeWidth = width;
  run.frame->eyeHeight = height;
  run.run();
}

}  // namespace

TEST(AnimatedFrames, FrameAtTimeEqualsStaticSceneAtItsPose) {
  const TempDirectory dir("penumbra_animated_frames");
  writeSquare(dir);
  std::vector<std::string> warnings;
  const Scene animated = loadSceneFile(dir.write("animated.json", kAnimated), warnings);
  const Scene still = loadSceneFile(dir.write("still.json", kStaticAtOne), warnings);
  ASSERT_FALSE(animated.animation.empty());
  // The geometry itself first: the pose at 1 is the static scene's, bit for bit.
  const Scene posed = poseAt(animated, 1);
  ASSERT_EQ(posed.objects.size(), still.objects.size());
  for (size_t i = 0; i < posed.objects.size(); ++i) {
    EXPECT_EQ(posed.objects[i].mesh.positions, still.objects[i].mesh.positions) << i;
    EXPECT_EQ(posed.objects[i].mesh.normals, still.objects[i].mesh.normals) << i;
  }
  EXPECT_EQ(posed.light.center, still.light.center);
  EXPECT_EQ(posed.light.width, still.light.width);

  // One pipeline runs t = 0 first, then t = 1; another runs only the static scene.
  PipelineRun moving(poseAt(animated, 0), kEveryMethod, 48, 40);
  const std::vector<float> atZero = moving.read("composite.color");
  moveTo(moving, poseAt(animated, 1));
  PipelineRun reference(still, kEveryMethod, 48, 40);
  EXPECT_NE(atZero, moving.read("composite.color")) << "the pose at 1 changes the image";
  size_t compared = 0;
  for (const auto& [name, texture] : reference.frame->textures) {
    ASSERT_TRUE(moving.frame->textures.count(name)) << name << " missing at t = 1";
    const GlTexture& other = moving.frame->textures.at(name);
    ASSERT_EQ(texture.width(), other.width()) << name;
    ASSERT_EQ(texture.height(), other.height()) << name;
    for (int layer = 0; layer < std::max(texture.layers(), 1); ++layer) {
      const std::vector<float> want = texture.readFloats(layer), got = other.readFloats(layer);
      ASSERT_EQ(want.size(), got.size()) << name;
      EXPECT_EQ(std::memcmp(want.data(), got.data(), want.size() * sizeof(float)), 0)
          << name << " layer " << layer << " differs from the static scene's";
    }
    ++compared;
  }
  for (const char* method : {"trace.visibility", "ssm.visibility", "pcss.visibility",
                             "hard_shadow.visibility", "filter.visibility", "raster4d.visibility", "reference.visibility"})
    EXPECT_TRUE(reference.frame->textures.count(method)) << method << " was not compared";
  EXPECT_GT(compared, 10u);
}

// The reference's caches across time, with a disk cache of its own ($PENUMBRA_CACHE).
TEST(AnimatedFrames, ReferenceCacheFollowsThePoseAndBvhOnlyOccluders) {
  const TempDirectory dir("penumbra_animated_cache");
  writeSquare(dir);
  setenv("PENUMBRA_CACHE", (dir.path() / "cache").c_str(), 1);
  std::vector<std::string> warnings;
  const Scene animated = loadSceneFile(dir.write("animated.json", kAnimated), warnings);
  const std::vector<std::string> sets = {"reference.enabled=true", "reference.cache=true",
                                         "reference.samples=4"};
  PipelineRun run(poseAt(animated, 0), sets, 32, 24);
  const auto counter = [&](const char* name) { return run.frame->counters.at(name); };
  EXPECT_EQ(counter("reference.cacheHit"), 0);
  EXPECT_EQ(counter("reference.bvhBuilds"), 1);
  const std::vector<float> atZero = run.read("reference.visibility");

  // Only the camera moves: a new image (the receivers changed), the same BVH.
  Scene turned = poseAt(animated, 0);
  turned.camera.position = {0.5f, 3, 6};
  moveTo(run, turned);
  EXPECT_EQ(counter("reference.cacheHit"), 0);
  EXPECT_EQ(counter("reference.bvhBuilds"), 1) << "camera only: the BVH is reused";

  // The square moves (t = 1): the cache misses and the BVH is rebuilt.
  moveTo(run, poseAt(animated, 1));
  EXPECT_EQ(counter("reference.cacheHit"), 0) << "an object moved: the cached image is stale";
  EXPECT_EQ(counter("reference.bvhBuilds"), 2);
  EXPECT_NE(run.read("reference.visibility"), atZero);

  // Back at t = 0 with the first camera: the image from the disk cache, in a new pipeline
  // (no memory of the first run), equal to the first.
  PipelineRun again(poseAt(animated, 0), sets, 32, 24);
  EXPECT_EQ(again.frame->counters.at("reference.cacheHit"), 2) << "disk";
  EXPECT_EQ(again.read("reference.visibility"), atZero);
  // A time that poses everything as at 0 (the loop's next cycle) reuses it too.
  PipelineRun nextCycle(poseAt(animated, animated.animation.duration), sets, 32, 24);
  EXPECT_NE(nextCycle.frame->counters.at("reference.cacheHit"), 0);
  unsetenv("PENUMBRA_CACHE");
}
