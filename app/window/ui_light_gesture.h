// The area light in the scene views (docs/design.md#window):
// its rectangle drawn over every eye-sized view, and mouse gestures with Alt held:
//   Alt + left drag          moves the light horizontally, by the motion of the ground point
//                            under the cursor (so the light follows the cursor over the ground)
//   Alt + Shift + left drag  raises / lowers the light
//   Alt + right drag         turns it (yaw, pitch), as the "light yaw / pitch" sliders
//   Alt + wheel              scales width and height (Shift: width only, Ctrl: height only)
// The geometry below is pure (no ImGui) so tests/window/test_window_units.cpp checks it.
#pragma once
#include <array>
#include <glm/glm.hpp>

#include "scene/scene.h"

class UiState;
struct ViewPanel;

// 1. Geometry. Eye texels are continuous GL texel coordinates of an eye-sized output
//    (texel (i, j) covers [i, i+1] x [j, j+1], row 0 at the bottom).
std::array<glm::vec3, 4> lightCorners(const AreaLight& light);  // in order round the rectangle
// World point -> eye texel through the frame's clipFromWorld; false behind the eye.
bool eyeTexelOf(const glm::mat4& clipFromWorld, glm::ivec2 eyeSize, glm::vec3 world,
                glm::vec2& texel);
// Where the eye ray through `texel` meets the plane y = planeY in front of the eye.
bool groundPointAt(const glm::mat4& worldFromClip, glm::ivec2 eyeSize, glm::vec2 texel,
                   float planeY, glm::vec3& point);
// The lowest point of the scene (its ground): the plane the drag follows.
float groundHeight(const Scene& scene);
// Moves the light by the horizontal motion of the ground point under the cursor from `from`
// to `to` (eye texels). False, light unchanged, where a ray misses the ground (the horizon)
// or the step is longer than `maxStep` world units (a ray grazing the ground).
bool moveLightOnGround(AreaLight& light, const glm::mat4& worldFromClip, glm::ivec2 eyeSize,
                       glm::vec2 from, glm::vec2 to, float groundY, float maxStep);
// Width and height times the factors, kept in [kMinLightSize, kMaxLightSize].
void scaleLight(AreaLight& light, float widthFactor, float heightFactor);
// Yaw and pitch change in degrees; pitch stays in [-90, 0] (down to horizontal).
void turnLight(AreaLight& light, float yawDegrees, float pitchDegrees);
constexpr float kMinLightSize = 0.01f, kMaxLightSize = 50.0f;

// 2. ImGui: called by the texture view for an eye-sized output. `handleLightMouse` runs the
//    gestures above when Alt is held (returns true while the light moves, so the pipeline
//    previews as for the camera); `drawLightOutline` draws the rectangle, its centre, and
//    the line along its axis down to the ground.
bool handleLightMouse(UiState& state, ViewPanel& view, glm::ivec2 eyeSize, glm::vec2 origin,
                      glm::vec2 regionSize);
void drawLightOutline(const UiState& state, const ViewPanel& view, glm::ivec2 eyeSize,
                      glm::vec2 origin, glm::vec2 regionSize);
