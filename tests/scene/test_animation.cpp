// Keyframed scenes (app/scene/animation.h): interpolation against keyframes computed by hand
// (linear, STEP, a rotation key more than 180 degrees from the last, which turns the shorter
// way), loop / ping-pong / once, the scene file's tracks and their refusals, and a glTF node
// animation written here against its pose worked out by hand.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include "base/input_error.h"
#include "scene/animation.h"
#include "scene/scene_builtin.h"
#include "scene/scene_file.h"
#include "scene/scene_gltf.h"
#include "support/temp_directory.h"

namespace {

constexpr double kEps = 1e-9;

void expectNear(const glm::dvec3& got, const glm::dvec3& want, double eps, const char* what) {
  EXPECT_NEAR(got.x, want.x, eps) << what;
  EXPECT_NEAR(got.y, want.y, eps) << what;
  EXPECT_NEAR(got.z, want.z, eps) << what;
}

glm::dquat aboutY(double degrees) {
  return glm::angleAxis(glm::radians(degrees), glm::dvec3(0, 1, 0));
}

}  // namespace

TEST(Animation, LinearTrackMatchesHandComputedKeys) {
  Vec3Track track;
  track.times = {0, 2, 4};
  track.values = {{0, 0, 0}, {2, 4, 0}, {2, 4, 8}};
  expectNear(sampleTrack(track, 1), {1, 2, 0}, kEps, "halfway to key 1");
  expectNear(sampleTrack(track, 3), {2, 4, 4}, kEps, "halfway to key 2");
  expectNear(sampleTrack(track, 3.5), {2, 4, 6}, kEps, "three quarters to key 2");
  expectNear(sampleTrack(track, 2), {2, 4, 0}, kEps, "on key 1");
  expectNear(sampleTrack(track, -1), {0, 0, 0}, kEps, "before the first key: the first");
  expectNear(sampleTrack(track, 9), {2, 4, 8}, kEps, "after the last key: the last");
  ScalarTrack width;
  width.times = {1, 3};
  width.values = {1, 2};
  EXPECT_DOUBLE_EQ(sampleTrack(width, 2.5), 1.75);
}

TEST(Animation, StepTrackHoldsEachKeyUntilTheNext) {
  ScalarTrack track;
  track.times = {0, 1, 2};
  track.values = {10, 20, 30};
  track.interpolation = Interpolation::Step;
  EXPECT_EQ(sampleTrack(track, 0.999), 10);
  EXPECT_EQ(sampleTrack(track, 1.0), 20);
  EXPECT_EQ(sampleTrack(track, 1.5), 20);
  EXPECT_EQ(sampleTrack(track, 7), 30);
}

// Keys 0 and 270 degrees about y: the shorter arc is 90 degrees backwards, so halfway is
// -45 degrees (x turns to (cos 45, 0, sin 45)), not +135.
TEST(Animation, SlerpPast180DegreesTakesTheShorterArc) {
  QuatTrack track;
  track.times = {0, 1};
  track.values = {aboutY(0), aboutY(270)};
  const glm::dvec3 x(1, 0, 0);
  const double h = std::sqrt(0.5);
  expectNear(sampleTrack(track, 0.5) * x, {h, 0, h}, 1e-12, "halfway: -45 degrees");
  const double a = glm::radians(22.5);
  expectNear(sampleTrack(track, 0.25) * x, {std::cos(a), 0, std::sin(a)}, 1e-12,
             "a quarter: -22.5 degrees");
  expectNear(sampleTrack(track, 1) * x, {0, 0, 1}, 1e-12, "the last key: 270 = -90 degrees");
  // Under 180 degrees it goes forwards: 0 -> 170, halfway +85.
  track.values = {aboutY(0), aboutY(170)};
  const double b = glm::radians(85.0);
  expectNear(sampleTrack(track, 0.5) * x, {std::cos(b), 0, -std::sin(b)}, 1e-12, "+85 degrees");
}

TEST(Animation, LoopPingPongAndOnceMapTimeIntoTheCycle) {
  Animation animation;
  animation.duration = 2;
  animation.repeat = Repeat::Loop;
  EXPECT_DOUBLE_EQ(animation.cycleTime(2.5), 0.5);
  EXPECT_DOUBLE_EQ(animation.cycleTime(-0.5), 1.5);
  animation.repeat = Repeat::PingPong;
  EXPECT_DOUBLE_EQ(animation.cycleTime(0.5), 0.5);
  EXPECT_DOUBLE_EQ(animation.cycleTime(2.5), 1.5);  // on the way back
  EXPECT_DOUBLE_EQ(animation.cycleTime(3.0), 1.0);
  EXPECT_DOUBLE_EQ(animation.cycleTime(4.5), 0.5);  // forwards again
  animation.repeat = Repeat::Once;
  EXPECT_DOUBLE_EQ(animation.cycleTime(5), 2);
  EXPECT_DOUBLE_EQ(animation.cycleTime(-1), 0);
}

namespace {

const char* kAnimatedScene = R"({
  "name": "animated",
  "objects": [
    {"ground": {"size": 2}, "name": "turning",
     "animation": {"rotate_degrees": {"times": [0, 1], "values": [[0, 0, 0], [0, 90, 0]]},
                   "translate": {"times": [0, 2], "values": [[0, 0, 0], [0, 2, 0]],
                                 "interpolation": "step"}}},
    {"ground": {"size": 4, "y": -1}, "name": "still"}
  ],
  "light": {"center": [0, 4, 0], "forward": [0, -1, 0], "up": [0, 0, -1], "width": 1, "height": 1,
            "animation": {"center": {"times": [0, 2], "values": [[0, 4, 0], [2, 4, 0]]},
                          "width": {"times": [0, 2], "values": [1, 3]},
                          "rotate_degrees": {"times": [0, 2], "values": [[0, 0, 0], [0, 0, 90]]}}},
  "camera": {"position": [0, 3, 6], "target": [0, 0, 0]},
  "animation": {"duration": 2, "repeat": "ping_pong"}
})";

bool hasVertex(const Mesh& mesh, const glm::dvec3& want, double eps) {
  for (const glm::vec3& p : mesh.positions)
    if (glm::length(glm::dvec3(p) - want) < eps) return true;
  return false;
}

}  // namespace

TEST(Animation, SceneFileTracksPoseObjectsAndLight) {
  const TempDirectory dir("penumbra_animation");
  std::vector<std::string> warnings;
  const Scene scene = loadSceneFile(dir.write("animated.json", kAnimatedScene), warnings);
  ASSERT_FALSE(scene.animation.empty());
  EXPECT_EQ(scene.animation.duration, 2);
  EXPECT_EQ(scene.animation.repeat, Repeat::PingPong);

  // t = 0.5: the 2x2 quad turned 45 degrees about y through its centre: its corner (1, 0, 1)
  // at (sqrt 2, 0, 0); the STEP translation still at its first key.
  const Scene half = poseAt(scene, 0.5);
  EXPECT_TRUE(half.animation.empty());
  EXPECT_TRUE(hasVertex(half.objects[0].mesh, {std::sqrt(2.0), 0, 0}, 1e-6));
  EXPECT_TRUE(hasVertex(half.objects[0].mesh, {-std::sqrt(2.0), 0, 0}, 1e-6));
  EXPECT_EQ(half.objects[1].mesh.positions, scene.objects[1].mesh.positions) << "not animated";
  // The light at t = 1 (halfway on every linear track): centre (1, 4, 0), width 2, turned 45
  // degrees about z: forward (0, -1, 0) -> (sin 45, -cos 45, 0).
  const Scene one = poseAt(scene, 1);
  expectNear(glm::dvec3(one.light.center), {1, 4, 0}, 1e-6, "light centre");
  EXPECT_FLOAT_EQ(one.light.width, 2.0f);
  EXPECT_FLOAT_EQ(one.light.height, 1.0f);
  const double h = std::sqrt(0.5);
  expectNear(glm::dvec3(one.light.forward), {h, -h, 0}, 1e-6, "light forward");
  // Ping-pong: t = 3 is t = 1 on the way back; t = 2 reaches the STEP key (y + 2).
  EXPECT_EQ(poseAt(scene, 3).objects[0].mesh.positions, one.objects[0].mesh.positions);
  EXPECT_TRUE(hasVertex(poseAt(scene, 2).objects[0].mesh, {-1, 2, 1}, 1e-6));  // 90 deg + step
  // Normals turn with the mesh and stay unit length.
  for (const glm::vec3& n : half.objects[0].mesh.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
}

TEST(Animation, StaticSceneIsUnchangedByPose) {
  const Scene scene = makeBuiltinScene("cube");
  const Scene posed = poseAt(scene, 1.25);
  ASSERT_EQ(posed.objects.size(), scene.objects.size());
  for (size_t i = 0; i < scene.objects.size(); ++i)
    EXPECT_EQ(posed.objects[i].mesh.positions, scene.objects[i].mesh.positions);
}

// Every bad track is refused naming the file, the JSON pointer and the problem.
TEST(Animation, BadTracksRefusedWithPointer) {
  const TempDirectory dir("penumbra_animation_bad");
  auto refusal = [&](const std::string& animation) {
    const std::string text =
        R"({"objects": [{"ground": {"size": 2}, "animation": )" + animation +
        R"(}], "light": {"center": [0, 4, 0], "forward": [0, -1, 0], "up": [0, 0, -1],
            "width": 1, "height": 1}, "camera": {"position": [0, 3, 6], "target": [0, 0, 0]}})";
    const std::string path = dir.write("bad.json", text);
    std::vector<std::string> warnings;
    try {
      loadSceneFile(path, warnings);
    } catch (const InputError& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
      return message.substr(path.size() + 2);
    }
    ADD_FAILURE() << animation << " was accepted";
    return std::string();
  };
  EXPECT_EQ(refusal(R"({"translate": {"times": [0, 1, 1], "values": [[0,0,0],[1,0,0],[2,0,0]]}})"),
            "/objects/0/animation/translate/times/2: times must increase: 1 is not after 1");
  EXPECT_EQ(refusal(R"({"translate": {"times": [0, 2, 1], "values": [[0,0,0],[1,0,0],[2,0,0]]}})"),
            "/objects/0/animation/translate/times/2: times must increase: 1 is not after 2");
  EXPECT_EQ(refusal(R"({"translate": {"times": [0, 1], "values": [[0,0,0],[1,0]]}})"),
            "/objects/0/animation/translate/values/1: expected an array of 3 numbers, got an "
            "array of 2");
  EXPECT_EQ(refusal(R"({"translate": {"times": [0, 1], "values": [[0,0,0]]}})"),
            "/objects/0/animation/translate/values: 1 values for 2 times (one value per time)");
  EXPECT_EQ(refusal(R"({"rotate_degrees": {"times": [0, 1], "values": [[0,0,0],[0,1e300,0]]}})"),
            "/objects/0/animation/rotate_degrees/values/1/1: must be finite and within +-1e30, "
            "got 1e+300");
  EXPECT_EQ(refusal(R"({"scale": {"times": [0, 1], "values": [1, 0]}})"),
            "/objects/0/animation/scale/values/1: must be positive (a number or an array of 3 "
            "positive numbers)");
  EXPECT_EQ(refusal(R"({"scale": {"times": [-1, 1], "values": [1, 2]}})"),
            "/objects/0/animation/scale/times/0: must not be negative, got -1");
  EXPECT_EQ(refusal(R"({"scale": {"times": [0], "values": [1], "interpolation": "cubic"}})"),
            "/objects/0/animation/scale/interpolation: unknown interpolation 'cubic' (valid: "
            "linear, step)");
  EXPECT_EQ(refusal(R"({"spin": {}})"),
            "/objects/0/animation: unknown key 'spin' (valid keys: pivot, translate, "
            "rotate_degrees, scale)");
  EXPECT_EQ(refusal(R"({"translate": {"times": [], "values": []}})"),
            "/objects/0/animation/translate/times: expected a non-empty array of times "
            "(seconds), got an array");
}

namespace {

// A glTF written here: node 0 (translation (0, 1, 0)) parents node 1, which holds a
// triangle (0,0,0), (1,0,0), (0,0,1) and is animated: translation LINEAR (0,0,0) -> (2,0,0)
// over [0, 1], rotation STEP identity -> 90 degrees about y at t = 1.
std::string writeAnimatedGltf(const TempDirectory& dir) {
  std::string bin;
  auto put = [&](std::initializer_list<float> values) {
    for (float v : values) bin.append(reinterpret_cast<const char*>(&v), 4);
  };
  put({0, 0, 0, 1, 0, 0, 0, 0, 1});                                     // 0: positions, 36
  put({0, 1});                                                          // 36: times, 8
  put({0, 0, 0, 2, 0, 0});                                              // 44: translations, 24
  const float h = static_cast<float>(std::sqrt(0.5));
  put({0, 0, 0, 1, 0, h, 0, h});                                        // 68: rotations, 32
  dir.write("anim.bin", bin);
  const std::string gltf = R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"translation": [0, 1, 0], "children": [1]}, {"mesh": 0}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
    "accessors": [
      {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,0], "max": [1,0,1]},
      {"bufferView": 1, "componentType": 5126, "count": 2, "type": "SCALAR", "min": [0], "max": [1]},
      {"bufferView": 2, "componentType": 5126, "count": 2, "type": "VEC3"},
      {"bufferView": 3, "componentType": 5126, "count": 2, "type": "VEC4"}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                    {"buffer": 0, "byteOffset": 36, "byteLength": 8},
                    {"buffer": 0, "byteOffset": 44, "byteLength": 24},
                    {"buffer": 0, "byteOffset": 68, "byteLength": 32}],
    "buffers": [{"uri": "anim.bin", "byteLength": 100}],
    "animations": [{"name": "slide", "channels": [
        {"sampler": 0, "target": {"node": 1, "path": "translation"}},
        {"sampler": 1, "target": {"node": 1, "path": "rotation"}}],
      "samplers": [{"input": 1, "output": 2, "interpolation": "LINEAR"},
                   {"input": 1, "output": 3, "interpolation": "STEP"}]}]})";
  return dir.write("anim.gltf", gltf);
}

}  // namespace

TEST(Animation, GltfNodeAnimationPosesAsComputedByHand) {
  const TempDirectory dir("penumbra_gltf_animation");
  const std::string path = writeAnimatedGltf(dir);
  std::vector<std::string> warnings;
  GltfAnimation animation;
  // Placed in the world 3 units along z, to check the placement is kept.
  const glm::mat4 world = glm::translate(glm::mat4(1), {0, 0, 3});
  Scene scene;
  scene.objects = loadGltf(path, world, warnings, nullptr, &animation);
  ASSERT_EQ(scene.objects.size(), 1u);
  ASSERT_EQ(animation.motions.size(), 1u);
  EXPECT_EQ(animation.name, "slide");
  scene.animation.objects = animation.motions;
  scene.animation.duration = scene.animation.endTime();
  EXPECT_EQ(scene.animation.duration, 1);
  scene.animation.repeat = Repeat::Once;
  // Rest: the first keys (translation 0, identity) under the parent's (0, 1, 0), + z 3.
  const auto& rest = scene.objects[0].mesh.positions;
  expectNear(glm::dvec3(rest[1]), {1, 1, 3}, 1e-6, "rest vertex 1");
  // t = 0.5: translation (1, 0, 0), the STEP rotation still identity.
  const Mesh half = poseAt(scene, 0.5).objects[0].mesh;
  expectNear(glm::dvec3(half.positions[0]), {1, 1, 3}, 1e-6, "t=0.5 vertex 0");
  expectNear(glm::dvec3(half.positions[1]), {2, 1, 3}, 1e-6, "t=0.5 vertex 1");
  expectNear(glm::dvec3(half.positions[2]), {1, 1, 4}, 1e-6, "t=0.5 vertex 2");
  // t = 1 (and after, clamped): translation (2, 0, 0), 90 degrees about y: x -> -z, z -> x.
  for (double t : {1.0, 5.0}) {
    const Mesh end = poseAt(scene, t).objects[0].mesh;
    expectNear(glm::dvec3(end.positions[0]), {2, 1, 3}, 1e-6, "t=1 vertex 0");
    expectNear(glm::dvec3(end.positions[1]), {2, 1, 2}, 1e-6, "t=1 vertex 1");
    expectNear(glm::dvec3(end.positions[2]), {3, 1, 3}, 1e-6, "t=1 vertex 2");
  }
  // The same file as a bare glTF scene: the ground first, the model scaled onto it; the
  // animation follows the model (vertex 1 moves by the placement's scale x 2 at t = 1).
  std::vector<std::string> sceneWarnings;
  const Scene bare = loadScene(path, sceneWarnings);
  ASSERT_EQ(bare.animation.objects.size(), 1u);
  EXPECT_EQ(bare.animation.objects[0].objects, std::vector<size_t>{1});
  EXPECT_EQ(bare.animation.duration, 1);
  const glm::dvec3 a = bare.objects[1].mesh.positions[0];
  const glm::dvec3 b = poseAt(bare, 0.5).objects[1].mesh.positions[0];
  const double scale = 2.5;  // the triangle is 1 across, placed 2.5 across
  expectNear(b - a, {scale * 1, 0, 0}, 1e-5, "bare glTF moved with its placement");
}

TEST(Animation, GltfBadSamplersRefused) {
  const TempDirectory dir("penumbra_gltf_animation_bad");
  const std::string good = writeAnimatedGltf(dir);
  std::ifstream in(good);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto refusal = [&](const std::string& from, const std::string& to) {
    std::string changed = text;
    const size_t at = changed.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    changed.replace(at, from.size(), to);
    const std::string path = dir.write("bad.gltf", changed);
    std::vector<std::string> warnings;
    GltfAnimation animation;
    try {
      loadGltf(path, glm::mat4(1), warnings, nullptr, &animation);
    } catch (const InputError& error) {
      return std::string(error.what()).substr(path.size() + 2);
    }
    ADD_FAILURE() << to << " accepted";
    return std::string();
  };
  EXPECT_EQ(refusal(R"("interpolation": "STEP")", R"("interpolation": "CUBICSPLINE")"),
            "/animations/0/samplers/1/interpolation: 'CUBICSPLINE' interpolation is not "
            "supported (LINEAR or STEP)");
  EXPECT_EQ(refusal(R"({"input": 1, "output": 3,)", R"({"input": 1, "output": 2,)"),
            "/accessors/2: keyframe accessor (/animations/0/samplers/1/output) has 3 components "
            "per element, expected 4");
  EXPECT_EQ(refusal(R"("path": "rotation")", R"("path": "spin")"),
            "/animations/0/channels/1/target/path: unknown path 'spin' (valid: translation, "
            "rotation, scale, weights)");
  EXPECT_EQ(refusal(R"("node": 1, "path": "translation")", R"("node": 7, "path": "translation")"),
            "/animations/0/channels/0/target/node: node 7 out of range (2 nodes)");
}

// The built-in animated scenes: valid at every quarter of their cycle, and moving.
TEST(Animation, BuiltinAnimatedScenesMoveAndStayValid) {
  for (const char* name : {"dragon_turntable", "light_sweep", "toys"}) {
    std::vector<std::string> warnings;
    const Scene scene = loadScene(name, warnings);
    ASSERT_FALSE(scene.animation.empty()) << name;
    ASSERT_GT(scene.animation.duration, 0) << name;
    const Scene start = poseAt(scene, 0);
    for (int quarter = 1; quarter <= 4; ++quarter) {
      const double t = scene.animation.duration * quarter / 4;
      EXPECT_EQ(posedSceneProblem(scene, t), "") << name << " at " << t;
      const Scene posed = poseAt(scene, t);
      bool moved = posed.light.center != start.light.center || posed.light.width != start.light.width;
      for (size_t i = 0; i < posed.objects.size(); ++i)
        moved = moved || posed.objects[i].mesh.positions != start.objects[i].mesh.positions;
      // A loop's end is its start again; ping-pong's end is the far end.
      if (quarter < 4 || scene.animation.repeat != Repeat::Loop) {
        EXPECT_TRUE(moved) << name << " at " << t;
      }
    }
  }
  // The light sweep widens the light from 0.4 to 2.4 over its 3 s and back.
  std::vector<std::string> warnings;
  const Scene sweep = loadScene("light_sweep", warnings);
  EXPECT_FLOAT_EQ(poseAt(sweep, 0).light.width, 0.4f);
  EXPECT_FLOAT_EQ(poseAt(sweep, 1.5).light.width, 1.4f);
  EXPECT_FLOAT_EQ(poseAt(sweep, 3).light.width, 2.4f);
  EXPECT_FLOAT_EQ(poseAt(sweep, 4.5).light.width, 1.4f);  // on the way back
}
