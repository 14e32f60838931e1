// The window's logic without a window: zoom/pan mapping, camera and light control, settings
// JSON (round trip, all-or-nothing errors), script parsing, export file names.
#include <gtest/gtest.h>

#include <cmath>

#include "scene_builtin.h"
#include "ui_camera.h"
#include "ui_export.h"
#include "ui_nbuffer_hover.h"
#include "ui_script.h"
#include "ui_settings.h"
#include "ui_state.h"
#include "ui_view_transform.h"

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
  state.scene = makeBuiltinScene("cube");
  state.sceneSource = "cube";
}
}  // namespace

TEST(WindowUnits, SettingsRoundTripEveryParameterCameraLightAndEye) {
  UiState original;
  useCube(original);
  original.scene.camera.position = {1.25f, 2.5f, 7.125f};
  original.scene.light.width = 0.75f;
  original.eye = {false, 320, 200};
  for (const std::string& key : original.pipeline.paramKeys()) {
    Param& param = original.pipeline.param(key);
    param.value = param.type == Param::Type::Float ? param.min + (param.max - param.min) / 3.0
                                                   : param.max;  // exactly representable
  }
  const json saved = settingsJson(original);
  UiState loaded;
  useCube(loaded);
  ASSERT_EQ(applySettingsJson(loaded, json::parse(saved.dump())), "");
  for (const std::string& key : original.pipeline.paramKeys())
    EXPECT_EQ(loaded.pipeline.param(key).value, original.pipeline.param(key).value) << key;
  EXPECT_EQ(loaded.scene.camera.position, original.scene.camera.position);
  EXPECT_EQ(loaded.scene.light.width, 0.75f);
  EXPECT_FALSE(loaded.eye.fitView);
  EXPECT_EQ(loaded.eye.width, 320);
  EXPECT_EQ(settingsJson(loaded), saved);
}

TEST(WindowUnits, BadSettingsChangeNothingAndNameThePath) {
  UiState state;
  useCube(state);
  const json before = settingsJson(state);
  const auto apply = [&](const json& settings) { return applySettingsJson(state, settings); };
  // A valid parameter first (keys are read in order), then a bad one: neither is applied.
  std::string problem = apply({{"parameters", {{"light_layers.fov_degrees", 60}, {"nope.key", 1}}}});
  EXPECT_NE(problem.find("/parameters/nope.key"), std::string::npos) << problem;
  EXPECT_NE(problem.find("light_layers.resolution"), std::string::npos) << problem;  // valid keys
  problem = apply({{"parameters", {{"light_layers.resolution", 5000}}}});
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
  EXPECT_NE(problem.find("integer >= 0"), std::string::npos) << problem;
  problem = parseScriptJson(json::parse(R"([{"wait": 1, "pick": [1, 2]}])"), actions);
  EXPECT_NE(problem.find("one key"), std::string::npos) << problem;
  EXPECT_NE(parseScriptJson(json::parse(R"({"wait": 1})"), actions), "");
}

TEST(WindowUnits, ExportNamesSaySceneOutputAndChangedParameters) {
  UiState state;
  useCube(state);
  EXPECT_EQ(exportStem(state, "hard_shadow.visibility", 0), "cube_hard_shadow.visibility");
  ASSERT_EQ(state.setParameter("hard_shadow.bias", "0.02"), "");
  ASSERT_EQ(state.setParameter("light_layers.resolution", "256"), "");  // another stage's
  const std::string stem = exportStem(state, "hard_shadow.visibility", 0);
  EXPECT_EQ(stem, "cube_hard_shadow.visibility_bias-0.02");
}

TEST(WindowUnits, NBufferHoverWindowSpansTwoToTheLevelInsideTheMap) {
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
