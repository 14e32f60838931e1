// The window's logic without a window: zoom/pan mapping, camera and light control (sliders and
// the Alt gestures' geometry), settings JSON (round trip, all-or-nothing errors), script
// parsing, lessons (interactive stepping, export directories), export file names.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "scene/scene_builtin.h"
#include "window/ui_camera.h"
#include "window/panels/ui_export.h"
#include "window/panels/ui_export_annotation.h"
#include "window/ui_light_gesture.h"
#include "window/views/ui_nbuffer_hover.h"
#include "window/script/ui_script.h"
#include "window/script/ui_settings.h"
#include "window/ui_state.h"
#include "window/views/ui_view_transform.h"

using nlohmann::json;

TEST(WindowUnits, ViewTransformMapsBothWaysAndZoomKeepsTheCursorTexel) {
  ViewTransform t;
  const glm::vec2 origin{100, 50}, region{400, 300};
  t.fit({200, 100}, region);
  EXPECT_FLOAT_EQ(t.zoom, 2.0f);  // 400/200 = 2 < 300/100 = 3
  // Texel (0, 0) is at the bottom-left of the image, which is centred in the region.
  const glm::vec2 bottomLeft = t.screenFromTexel({0, 0}, origin, region);
  EXPECT_FLOAT_EQ(bottomLeft.x, 100.0f);
  EXPECT_FLOAT_EQ(bottomLeft.y, 50 + 150 + 100.0f);
  EXPECT_EQ(t.texelAt({101, 50 + 150 + 99}, origin, region), glm::ivec2(0, 0));
  EXPECT_EQ(t.texelAt({499, 50 + 150 - 99}, origin, region), glm::ivec2(199, 99));
  const glm::vec2 cursor{180, 120};
  const glm::vec2 before = t.texelFromScreen(cursor, origin, region);
  t.zoomAbout(3.7f, cursor, origin, region);
  const glm::vec2 after = t.texelFromScreen(cursor, origin, region);
  EXPECT_NEAR(before.x, after.x, 1e-4);
  EXPECT_NEAR(before.y, after.y, 1e-4);
  t.pan({10, 0});  // dragging right moves the image right: the centre texel moves left
  EXPECT_NEAR(t.texelFromScreen(cursor + glm::vec2(10, 0), origin, region).x, after.x, 1e-4);
  glm::ivec2 lo, hi;
  t.fit({200, 100}, region);
  t.visibleTexels(region, {200, 100}, lo, hi);
  EXPECT_EQ(lo, glm::ivec2(0, 0));
  EXPECT_EQ(hi, glm::ivec2(200, 100));
}

TEST(WindowUnits, OrbitKeepsDistanceAndTargetDollyScalesPanMovesBoth) {
  Camera camera{{0.5f, 3.6f, 5.6f}, {0, 0.3f, 0}, {0, 1, 0}, 45};
  const float distance = glm::distance(camera.position, camera.target);
  orbitCamera(camera, 0.7f, 0.3f);
  EXPECT_NEAR(glm::distance(camera.position, camera.target), distance, 1e-4);
  EXPECT_EQ(camera.target, glm::vec3(0, 0.3f, 0));
  for (int i = 0; i < 50; ++i) orbitCamera(camera, 0, 0.2f);  // never over the pole
  EXPECT_LT(std::abs(glm::dot(glm::normalize(camera.position - camera.target), camera.up)), 0.999f);
  dollyCamera(camera, 0.5f);
  EXPECT_NEAR(glm::distance(camera.position, camera.target), 0.5f * distance, 1e-4);
  const glm::vec3 offset = camera.position - camera.target;
  panCamera(camera, 0.1f, -0.2f);
  EXPECT_NEAR(glm::length(camera.position - camera.target - offset), 0, 1e-5);
  EXPECT_NE(camera.target, glm::vec3(0, 0.3f, 0));
}

TEST(WindowUnits, LightAnglesRoundTripAndKeepTheFrameOrthonormal) {
  AreaLight light;
  for (float yaw : {-150.0f, -30.0f, 0.0f, 75.0f})
    for (float pitch : {-89.0f, -60.0f, -10.0f}) {
      setLightAngles(light, yaw, pitch);
      float yawBack = 0, pitchBack = 0;
      lightAngles(light, yawBack, pitchBack);
      EXPECT_NEAR(yawBack, yaw, 1e-2) << pitch;
      EXPECT_NEAR(pitchBack, pitch, 1e-2);
      EXPECT_NEAR(glm::length(light.up), 1, 1e-5);
      EXPECT_NEAR(glm::dot(light.up, light.forward), 0, 1e-5);
    }
  setLightAngles(light, 0, -90);  // straight down: up must still be valid
  EXPECT_NEAR(glm::dot(light.up, light.forward), 0, 1e-5);
  EXPECT_NEAR(glm::length(light.up), 1, 1e-5);
}

namespace {
// A state on the cube scene without GL (adoptScene would build GPU buffers).
void useCube(UiState& state) {
  state.session.scene = makeBuiltinScene("cube");
  state.session.sceneSource = "cube";
}
}  // namespace

TEST(WindowUnits, SettingsRoundTripEveryParameterCameraLightAndEye) {
  UiState original;
  useCube(original);
  original.session.scene.camera.position = {1.25f, 2.5f, 7.125f};
  original.session.scene.light.width = 0.75f;
  original.session.eye = {false, 320, 200};
  for (const std::string& key : original.session.pipeline.paramKeys()) {
    Param& param = original.session.pipeline.param(key);
    param.value = param.type == Param::Type::Float ? param.min + (param.max - param.min) / 3.0
                                                   : param.max;  // exactly representable
    param.automatic = false;  // `auto` (docs/accuracy.md) is saved as "auto", not as the value
  }
  const json saved = settingsJson(original);
  UiState loaded;
  useCube(loaded);
  ASSERT_EQ(applySettingsJson(loaded, json::parse(saved.dump())), "");
  for (const std::string& key : original.session.pipeline.paramKeys()) {
    EXPECT_EQ(loaded.session.pipeline.param(key).value, original.session.pipeline.param(key).value) << key;
    EXPECT_FALSE(loaded.session.pipeline.param(key).automatic) << key;
  }
  // And `auto` round-trips as itself.
  original.session.pipeline.param("light.resolution").automatic = true;
  UiState reloaded;
  useCube(reloaded);
  ASSERT_EQ(applySettingsJson(reloaded, json::parse(settingsJson(original).dump())), "");
  EXPECT_TRUE(reloaded.session.pipeline.param("light.resolution").automatic);
  EXPECT_EQ(loaded.session.scene.camera.position, original.session.scene.camera.position);
  EXPECT_EQ(loaded.session.scene.light.width, 0.75f);
  EXPECT_FALSE(loaded.session.eye.fitView);
  EXPECT_EQ(loaded.session.eye.width, 320);
  EXPECT_EQ(settingsJson(loaded), saved);
}

TEST(WindowUnits, BadSettingsChangeNothingAndNameThePath) {
  UiState state;
  useCube(state);
  const json before = settingsJson(state);
  const auto apply = [&](const json& settings) { return applySettingsJson(state, settings); };
  // A valid parameter first (keys are read in order), then a bad one: neither is applied.
  std::string problem = apply({{"parameters", {{"light.fov_degrees", 60}, {"nope.key", 1}}}});
  EXPECT_NE(problem.find("/parameters/nope.key"), std::string::npos) << problem;
  EXPECT_NE(problem.find("light.resolution"), std::string::npos) << problem;  // valid keys
  problem = apply({{"parameters", {{"light.resolution", 5000}}}});
  EXPECT_NE(problem.find("[128, 2048]"), std::string::npos) << problem;
  problem = apply({{"camera", {{"position", {1, 2}}}}});
  EXPECT_NE(problem.find("/camera/position"), std::string::npos) << problem;
  problem = apply({{"light", {{"width", -1}}}, {"eye", {640, 480}}});
  EXPECT_NE(problem.find("light"), std::string::npos) << problem;
  problem = apply({{"eye", "big"}});
  EXPECT_NE(problem.find("/eye"), std::string::npos) << problem;
  problem = apply({{"colour", 1}});
  EXPECT_NE(problem.find("unknown key"), std::string::npos) << problem;
  EXPECT_EQ(settingsJson(state), before);
}

TEST(WindowUnits, ScriptParsingNamesTheActionAndWhatIsValid) {
  std::vector<ScriptAction> actions;
  EXPECT_EQ(parseScriptJson(json::parse(R"([{"select_output": "trace.visibility"}, {"wait": 2},
      {"set": {"trace.rays": 3}}, {"pick": [10, 20]}, {"range": "autofit"}, {"zoom": "1:1"},
      {"eye_size": [64, 48]}, {"screenshot": "a.png"}])"), actions), "");
  ASSERT_EQ(actions.size(), 8u);
  EXPECT_EQ(actions[3].name, "pick");
  EXPECT_EQ(actions[3].index, 4u);
  std::string problem = parseScriptJson(json::parse(R"([{"wait": 1}, {"explode": true}])"), actions);
  EXPECT_NE(problem.find("script action 2"), std::string::npos) << problem;
  EXPECT_NE(problem.find("unknown action 'explode'"), std::string::npos) << problem;
  EXPECT_NE(problem.find("select_output"), std::string::npos) << problem;  // lists valid ones
  problem = parseScriptJson(json::parse(R"([{"pick": "middle"}])"), actions);
  EXPECT_NE(problem.find("(pick): expected [a, b]"), std::string::npos) << problem;
  problem = parseScriptJson(json::parse(R"([{"wait": -1}])"), actions);
  EXPECT_NE(problem.find("integer in [0, 100000]"), std::string::npos) << problem;
  problem = parseScriptJson(json::parse(R"([{"wait": 1, "pick": [1, 2]}])"), actions);
  EXPECT_NE(problem.find("one key"), std::string::npos) << problem;
  EXPECT_NE(parseScriptJson(json::parse(R"({"wait": 1})"), actions), "");
  // Integer arguments with a positive lower bound (JSON reads them as unsigned): inside the
  // range accepted, at its bounds too, outside refused.
  EXPECT_EQ(parseScriptJson(json::parse(R"([{"drag": {"from": [1, 2], "to": [3, 4], "frames": 60}},
    {"drag": {"from": [1, 2], "to": [3, 4], "frames": 1}}, {"drag": {"from": [1, 2], "to": [3, 4], "frames": 240}}])"),
                            actions), "");
  EXPECT_NE(parseScriptJson(json::parse(R"([{"drag": {"from": [1, 2], "to": [3, 4], "frames": 0}}])"), actions), "");
  EXPECT_NE(parseScriptJson(json::parse(R"([{"drag": {"from": [1, 2], "to": [3, 4], "frames": 241}}])"), actions), "");
  EXPECT_NE(parseScriptJson(json::parse(R"([{"drag": {"from": [1, 2], "to": [3, 4], "frames": -5}}])"), actions), "");
}

TEST(WindowUnits, ExportNamesSaySceneOutputAndChangedParameters) {
  UiState state;
  useCube(state);
  EXPECT_EQ(exportStem(state, "hard_shadow.visibility", 0), "cube_hard_shadow.visibility");
  ASSERT_EQ(state.session.setParameter("hard_shadow.offset", "0.02"), "");
  ASSERT_EQ(state.session.setParameter("light.resolution", "256"), "");  // another stage's
  const std::string stem = exportStem(state, "hard_shadow.visibility", 0);
  EXPECT_EQ(stem, "cube_hard_shadow.visibility_offset-0.02");
}

// An annotated PNG's caption: the shown stage's changed parameters by their short keys, then
// those of the stages it depends on (so the Atty lesson's SSM panels at two map sizes differ),
// never a stage it does not depend on.
TEST(WindowUnits, CaptionsNameTheChangedParametersTheOutputDependsOn) {
  UiState state;
  useCube(state);
  ViewPanel view;
  view.output = "hard_shadow.visibility";
  EXPECT_EQ(viewCaption(state, view), "cube · hard_shadow.visibility");
  ASSERT_EQ(state.session.setParameter("hard_shadow.offset", "0.02"), "");
  ASSERT_EQ(state.session.setParameter("light.resolution", "256"), "");  // a dependency
  ASSERT_EQ(state.session.setParameter("trace.rays", "3"), "");          // not one
  EXPECT_EQ(viewCaption(state, view),
            "cube · hard_shadow.visibility · offset=0.02, light.resolution=256");
}

TEST(WindowUnits, NBufferHoverWindowSpansTwoToTheLevelInsideTheMap) {
  // A view's level past the map's ("level": 40 from a script, UBSan: shift exponent 40)
  // spans the whole map, as the top level does.
  for (int level : {31, 40, 1000})
    EXPECT_EQ(nbufferWindow1D(level, 100, 512), glm::ivec2(0, 511)) << level;
  for (int size : {5, 64, 100})
    for (int level = 0; (1 << level) <= 2 * size; ++level)
      for (int x = 0; x < size; ++x) {
        const glm::ivec2 w = nbufferWindow1D(level, x, size);
        EXPECT_GE(w.x, 0);
        EXPECT_LT(w.y, size);
        EXPECT_EQ(w.y - w.x + 1, std::min(1 << level, size)) << size << " " << level << " " << x;
        if ((1 << level) <= size) {  // the texel lies in its own window
          EXPECT_LE(w.x, x);
          EXPECT_GE(w.y, x);
        }
      }
  glm::ivec2 lo, hi;
  nbufferWindow(3, {10, 0}, {64, 64}, lo, hi);  // centred where it can, shifted at the edge
  EXPECT_EQ(lo, glm::ivec2(6, 0));
  EXPECT_EQ(hi, glm::ivec2(13, 7));
}

namespace {
// Eye at (0, 5, 0) looking straight down, 90 degrees, square: the ground (y = 0) under eye
// texel (u, v) of a 100 x 100 image is x = 5 (2u/100 - 1), z = -5 (2v/100 - 1) (up is -z).
glm::mat4 downCamera() {
  const glm::mat4 view = glm::lookAt(glm::vec3(0, 5, 0), glm::vec3(0), glm::vec3(0, 0, -1));
  return glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 100.0f) * view;
}
}  // namespace

TEST(WindowUnits, LightGeometryProjectsAndDragsOverTheGroundAsTheCursorMoves) {
  const glm::mat4 clipFromWorld = downCamera(), worldFromClip = glm::inverse(clipFromWorld);
  const glm::ivec2 eye{100, 100};
  glm::vec3 ground;
  ASSERT_TRUE(groundPointAt(worldFromClip, eye, {75, 50}, 0, ground));
  EXPECT_NEAR(ground.x, 2.5f, 1e-4);
  EXPECT_NEAR(ground.z, 0.0f, 1e-4);
  ASSERT_TRUE(groundPointAt(worldFromClip, eye, {50, 90}, 0, ground));
  EXPECT_NEAR(ground.z, -4.0f, 1e-4);
  glm::vec2 texel;
  ASSERT_TRUE(eyeTexelOf(clipFromWorld, eye, {-2.5f, 0, 2.5f}, texel));
  EXPECT_NEAR(texel.x, 25, 1e-3);
  EXPECT_NEAR(texel.y, 25, 1e-3);
  EXPECT_FALSE(eyeTexelOf(clipFromWorld, eye, {0, 6, 0}, texel));  // behind the eye
  // A drag of 25 texels to the right moves the light 2.5 units along +x, nothing else.
  AreaLight light;
  light.center = {0.5f, 4, 0.25f};
  ASSERT_TRUE(moveLightOnGround(light, worldFromClip, eye, {50, 50}, {75, 50}, 0, 10));
  EXPECT_NEAR(light.center.x, 3.0f, 1e-4);
  EXPECT_NEAR(light.center.y, 4.0f, 1e-6);
  EXPECT_NEAR(light.center.z, 0.25f, 1e-4);
  EXPECT_FALSE(moveLightOnGround(light, worldFromClip, eye, {50, 50}, {75, 50}, 0, 1));  // > max
  EXPECT_NEAR(light.center.x, 3.0f, 1e-4);
  // Looking at the horizon, a texel above it never meets the ground: no move.
  const glm::mat4 level = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f) *
                          glm::lookAt(glm::vec3(0, 1, 0), glm::vec3(0, 1, -1), glm::vec3(0, 1, 0));
  EXPECT_FALSE(moveLightOnGround(light, glm::inverse(level), eye, {50, 20}, {50, 90}, 0, 10));
  EXPECT_NEAR(light.center.x, 3.0f, 1e-4);
}

TEST(WindowUnits, LightCornersScaleAndTurnKeepAValidRectangle) {
  AreaLight light;  // faces down, up = -z: right = forward x up = +x
  light.center = {1, 4, 2};
  light.width = 2;
  light.height = 1;
  const auto corners = lightCorners(light);
  for (const glm::vec3& c : corners) {
    EXPECT_NEAR(std::abs(c.x - 1), 1.0f, 1e-5);
    EXPECT_NEAR(c.y, 4.0f, 1e-6);
    EXPECT_NEAR(std::abs(c.z - 2), 0.5f, 1e-5);
  }
  EXPECT_NEAR(glm::distance(corners[0], corners[1]), 2.0f, 1e-5);  // consecutive: a side
  EXPECT_NEAR(glm::distance(corners[1], corners[2]), 1.0f, 1e-5);
  scaleLight(light, 1e6f, 0.5f);
  EXPECT_EQ(light.width, kMaxLightSize);
  EXPECT_FLOAT_EQ(light.height, 0.5f);
  scaleLight(light, 1e-9f, 1);
  EXPECT_EQ(light.width, kMinLightSize);
  setLightAngles(light, 20, -60);
  turnLight(light, 30, 100);  // pitch stops at horizontal
  float yaw = 0, pitch = 0;
  lightAngles(light, yaw, pitch);
  EXPECT_NEAR(yaw, 50, 1e-2);
  EXPECT_NEAR(pitch, 0, 1e-2);
  turnLight(light, 0, -500);
  lightAngles(light, yaw, pitch);
  EXPECT_NEAR(pitch, -90, 1e-2);
  Scene scene = makeBuiltinScene("cube");
  scene.light = light;
  EXPECT_EQ(validateScene(scene), "");
}

namespace {
std::vector<ScriptAction> parsed(const std::string& text) {
  std::vector<ScriptAction> actions;
  EXPECT_EQ(parseScriptJson(json::parse(text), actions), "");
  return actions;
}
}  // namespace

TEST(WindowUnits, InteractiveLessonWaitsForNextBeforeEachSayAfterTheFirst) {
  const std::string lesson = R"([{"lesson": "T"}, {"say": "one"}, {"set": {"trace.rays": 3}},
      {"say": "two"}, {"say": "three"}])";
  UiState state;
  useCube(state);
  ScriptRunner runner(parsed(lesson), ScriptOptions{true, "", ""});
  for (int i = 0; i < 6; ++i) EXPECT_EQ(runner.step(state), ScriptRunner::Step::Running);
  EXPECT_EQ(state.lesson.title, "T");
  EXPECT_EQ(state.lesson.text, "one");  // the student has not asked for more
  EXPECT_EQ(state.lesson.step, 1);
  EXPECT_EQ(state.lesson.steps, 3);
  EXPECT_TRUE(state.lesson.waiting);
  EXPECT_EQ(state.session.pipeline.param("trace.rays").asInt(), 3);  // the step's own actions ran
  state.lesson.next = true;
  EXPECT_EQ(runner.step(state), ScriptRunner::Step::Running);
  EXPECT_EQ(state.lesson.text, "two");
  EXPECT_FALSE(state.lesson.next);
  for (int i = 0; i < 3; ++i) runner.step(state);
  EXPECT_EQ(state.lesson.text, "two");
  state.lesson.next = true;
  runner.step(state);
  EXPECT_EQ(state.lesson.text, "three");
  EXPECT_EQ(runner.step(state), ScriptRunner::Step::Done);
  // Played through (a script, or `penumbra lesson --export`): nobody waits.
  UiState through;
  useCube(through);
  ScriptRunner all(parsed(lesson), ScriptOptions{false, "", ""});
  ScriptRunner::Step step = ScriptRunner::Step::Running;
  for (int i = 0; i < 20 && step == ScriptRunner::Step::Running; ++i) step = all.step(through);
  EXPECT_EQ(step, ScriptRunner::Step::Done);
  EXPECT_EQ(through.lesson.text, "three");
  EXPECT_EQ(through.lesson.step, 3);
}

TEST(WindowUnits, RelativeExportsGoIntoTheLessonsDirectoryOrTheOverride) {
  const std::string script = R"([{"export_dir": "from_script"}, {"screenshot": "a.png"},
      {"wait": 1}, {"screenshot": "/abs/b.png"}])";
  for (const std::string& override : {std::string(), std::string("/abs/override")}) {
    UiState state;
    useCube(state);
    ScriptRunner runner(parsed(script), ScriptOptions{false, override, ""});
    std::vector<std::string> requested;
    for (int i = 0; i < 12 && runner.step(state) == ScriptRunner::Step::Running; ++i)
      if (!state.script.screenshotRequest.empty()) {
        requested.push_back(state.script.screenshotRequest);
        state.script.screenshotRequest.clear();
      }
    ASSERT_EQ(requested.size(), 1u) << override;
    EXPECT_EQ(requested[0], (override.empty() ? "penumbra_exports/from_script" : override) + "/a.png");
    // With an export folder, an absolute path would write outside it: refused.
    EXPECT_NE(runner.error().find("absolute path"), std::string::npos) << runner.error();
  }
  std::vector<ScriptAction> actions;
  EXPECT_NE(parseScriptJson(json::parse(R"([{"say": 3}])"), actions).find("expected a string"),
            std::string::npos);
}

// A lesson's figures (docs/lessons.md) never land in the working directory itself: without --export
// and export_dir they go under the output folder in a folder named after the lesson's file.
TEST(WindowUnits, ALessonWithoutExportDirExportsUnderTheOutputFolderByItsName) {
  const std::string lesson = R"([{"lesson": "t"}, {"screenshot": "a.png"}])";
  for (const std::string& override : {std::string(), std::string("/tmp/chosen")}) {
    UiState state;
    useCube(state);
    ScriptRunner runner(parsed(lesson), ScriptOptions{false, override, "lessons/fig_9_9.json"});
    std::string requested;
    for (int i = 0; i < 12 && runner.step(state) == ScriptRunner::Step::Running; ++i)
      if (!state.script.screenshotRequest.empty()) requested = state.script.screenshotRequest;
    // A lesson's folder is one transaction: its files go into the folder's hidden temporary
    // sibling first (io/output_path.h), renamed into place when the lesson ends.
    const std::filesystem::path folder = std::filesystem::absolute(
        override.empty() ? std::string(kDefaultExportDirectory) + "/fig_9_9" : override);
    EXPECT_EQ(requested, (folder.parent_path() /
                          ("." + folder.filename().string() + ".partial-" + std::to_string(::getpid())) /
                          "a.png").string());
  }
  // export_dir names a folder under the output folder: no way out of it.
  std::vector<ScriptAction> actions;
  for (const char* bad : {R"([{"export_dir": "/tmp/x"}])", R"([{"export_dir": "a/../../x"}])",
                          R"([{"export_dir": ""}])"})
    EXPECT_NE(parseScriptJson(json::parse(bad), actions).find("(export_dir): expected a folder name"),
              std::string::npos) << bad;
  EXPECT_NE(parseScriptJson(json::parse(R"([{"export_view": {"file": "a.png", "colour": 1}}])"),
                            actions).find("\"colour\": expected"),
            std::string::npos);
}
