#include "window/ui_light_gesture.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "window/ui_camera.h"
#include "window/ui_graph.h"
#include "window/ui_state.h"
#include "window/views/texture_view.h"

// 1. Geometry.
std::array<glm::vec3, 4> lightCorners(const AreaLight& light) {
  // The same frame as computeLightFrame (app/scene/light_frame.cpp): right = forward x up.
  const glm::vec3 forward = glm::normalize(light.forward);
  const glm::vec3 right = glm::normalize(glm::cross(forward, light.up));
  const glm::vec3 up = glm::cross(right, forward);
  const glm::vec3 r = 0.5f * light.width * right, u = 0.5f * light.height * up;
  return {light.center - r - u, light.center + r - u, light.center + r + u, light.center - r + u};
}

bool eyeTexelOf(const glm::mat4& clipFromWorld, glm::ivec2 eyeSize, glm::vec3 world,
                glm::vec2& texel) {
  const glm::vec4 clip = clipFromWorld * glm::vec4(world, 1);
  if (!(clip.w > 1e-6f)) return false;  // behind (or at) the eye
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  texel = (0.5f * ndc + 0.5f) * glm::vec2(eyeSize);
  return std::isfinite(texel.x) && std::isfinite(texel.y);
}

bool groundPointAt(const glm::mat4& worldFromClip, glm::ivec2 eyeSize, glm::vec2 texel,
                   float planeY, glm::vec3& point) {
  const glm::vec2 ndc = 2.0f * texel / glm::vec2(eyeSize) - 1.0f;
  const glm::vec4 nearPoint = worldFromClip * glm::vec4(ndc, -1, 1);
  const glm::vec4 farPoint = worldFromClip * glm::vec4(ndc, 1, 1);
  const glm::vec3 a = glm::vec3(nearPoint) / nearPoint.w, b = glm::vec3(farPoint) / farPoint.w;
  const glm::vec3 direction = b - a;
  if (std::abs(direction.y) < 1e-9f) return false;  // parallel to the ground
  const float t = (planeY - a.y) / direction.y;
  if (!(t > 0)) return false;  // the ground lies behind the eye along this ray
  point = a + t * direction;
  return std::isfinite(point.x) && std::isfinite(point.z);
}

float groundHeight(const Scene& scene) {
  const Bounds bounds = scene.bounds();
  return bounds.empty() ? 0.0f : bounds.min.y;
}

bool moveLightOnGround(AreaLight& light, const glm::mat4& worldFromClip, glm::ivec2 eyeSize,
                       glm::vec2 from, glm::vec2 to, float groundY, float maxStep) {
  glm::vec3 a, b;
  if (!groundPointAt(worldFromClip, eyeSize, from, groundY, a) ||
      !groundPointAt(worldFromClip, eyeSize, to, groundY, b))
    return false;
  const glm::vec3 step{b.x - a.x, 0, b.z - a.z};
  if (glm::length(step) > maxStep) return false;
  light.center += step;
  return true;
}

void scaleLight(AreaLight& light, float widthFactor, float heightFactor) {
  light.width = std::clamp(light.width * widthFactor, kMinLightSize, kMaxLightSize);
  light.height = std::clamp(light.height * heightFactor, kMinLightSize, kMaxLightSize);
}

void turnLight(AreaLight& light, float yawDegrees, float pitchDegrees) {
  float yaw = 0, pitch = 0;
  lightAngles(light, yaw, pitch);
  yaw = std::remainder(yaw + yawDegrees, 360.0f);
  setLightAngles(light, yaw, std::clamp(pitch + pitchDegrees, -90.0f, 0.0f));
}

namespace {

float sceneSize(const Scene& scene) {
  const Bounds bounds = scene.bounds();
  return bounds.empty() ? 10.0f : std::max(glm::length(bounds.max - bounds.min), 1e-3f);
}

}  // namespace

// 2. Gestures (Alt held). The view's transform maps screen points to eye texels.
bool handleLightMouse(UiState& state, ViewPanel& view, glm::ivec2 eyeSize, glm::vec2 origin,
                      glm::vec2 regionSize) {
  if (!state.session.frame) return false;
  ImGuiIO& io = ImGui::GetIO();
  AreaLight& light = state.session.scene.light;
  const AreaLight before = light;
  if (ImGui::IsItemHovered() && io.MouseWheel != 0) {
    const float factor = std::pow(1.1f, io.MouseWheel);
    scaleLight(light, io.KeyCtrl ? 1.0f : factor, io.KeyShift ? 1.0f : factor);
  }
  const glm::vec2 mouse{io.MousePos.x, io.MousePos.y};
  const glm::vec2 delta{io.MouseDelta.x, io.MouseDelta.y};
  bool dragging = false;
  if (ImGui::IsItemActive() && ImGui::IsMouseDown(ImGuiMouseButton_Left) && delta != glm::vec2(0)) {
    dragging = true;
    if (io.KeyShift) {  // up / down: a drag over the view's height moves about the eye distance
      const float distance = glm::distance(state.session.scene.camera.position, light.center);
      light.center.y -= delta.y / std::max(regionSize.y, 1.0f) * distance;
    } else {
      const glm::vec2 to = view.transform.texelFromScreen(mouse, origin, regionSize);
      const glm::vec2 from = view.transform.texelFromScreen(mouse - delta, origin, regionSize);
      moveLightOnGround(light, state.session.frame->uniforms.worldFromClip, eyeSize, from, to,
                        groundHeight(state.session.scene), 0.5f * sceneSize(state.session.scene));
    }
  }
  if (ImGui::IsItemActive() && ImGui::IsMouseDown(ImGuiMouseButton_Right) && delta != glm::vec2(0)) {
    dragging = true;
    turnLight(light, delta.x * 0.4f, -delta.y * 0.4f);
  }
  if (ImGui::IsItemActive()) dragging = true;  // held still: keep the preview until release
  const bool changed = light.center != before.center || light.forward != before.forward ||
                       light.width != before.width || light.height != before.height;
  if (changed) {
    if (validateScene(state.session.scene).empty()) {
      char text[160];
      std::snprintf(text, sizeof text, "light at (%.2f, %.2f, %.2f), %.2f x %.2f", light.center.x,
                    light.center.y, light.center.z, light.width, light.height);
      state.status = text;
    } else {
      light = before;  // never hand the pipeline a broken light
    }
  }
  return dragging;
}

// 3. The picked pixel's occlusion mask (raster4d, docs/raster4d.md) on the light itself:
//    cell (i, j) of the m x m grid, row i along the light's up, column j along its right from
//    the corner -right -up (the samples' own layout), red where a triangle hides the sample,
//    grey where it lies behind the receiver's tangent plane. Read back once per pipeline run.
template <class Screen>
void drawLightMask(const UiState& state, const std::array<glm::vec3, 4>& corners, const Screen& screen) {
  LightMaskCache& cache = state.views.lightMask;
  std::vector<float>& mask = cache.mask;
  int& maskSide = cache.side;
  const std::string output = lightMaskOutput(state.session.pipeline);
  if (output.empty() || !state.views.pick || !state.session.frame->has(output)) return;
  if (cache.run != state.session.pipelineRuns) {
    const GlTexture& texture = state.session.frame->texture(output);
    maskSide = texture.width() == texture.height() ? texture.width() : 0;
    if (maskSide > 0) mask = readRegion(texture, 0, 0, maskSide, maskSide, 0);
    cache.run = state.session.pipelineRuns;
  }
  if (maskSide <= 0 || mask.size() < size_t(maskSide) * maskSide) return;
  const float m = float(maskSide);
  const glm::vec3 along = corners[1] - corners[0], upward = corners[3] - corners[0];
  ImDrawList* draw = ImGui::GetWindowDrawList();
  for (int i = 0; i < maskSide; ++i)
    for (int j = 0; j < maskSide; ++j) {
      const float value = mask[size_t(i) * maskSide + j];  // GL order: row 0 = light's -up
      if (value <= 0) continue;
      ImVec2 cell[4];
      bool visible = true;
      const float u[4] = {float(j), float(j + 1), float(j + 1), float(j)};
      const float v[4] = {float(i), float(i), float(i + 1), float(i + 1)};
      for (int k = 0; k < 4; ++k)
        visible = screen(corners[0] + (u[k] / m) * along + (v[k] / m) * upward, cell[k]) && visible;
      const ImU32 colour = value >= 1 ? IM_COL32(230, 40, 40, 200) : IM_COL32(120, 120, 120, 200);
      if (visible) draw->AddConvexPolyFilled(cell, 4, colour);
    }
}

// 4. Outline: a translucent quad, its border, the centre and the axis down to the ground.
void drawLightOutline(const UiState& state, const ViewPanel& view, glm::ivec2 eyeSize,
                      glm::vec2 origin, glm::vec2 regionSize) {
  if (!state.session.frame || !state.views.showLight) return;
  const glm::mat4& clipFromWorld = state.session.frame->uniforms.clipFromWorld;
  const AreaLight& light = state.session.scene.light;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const auto screen = [&](glm::vec3 world, ImVec2& at) {
    glm::vec2 texel;
    if (!eyeTexelOf(clipFromWorld, eyeSize, world, texel)) return false;
    const glm::vec2 s = view.transform.screenFromTexel(texel, origin, regionSize);
    at = {std::clamp(s.x, -1e5f, 1e5f), std::clamp(s.y, -1e5f, 1e5f)};
    return true;
  };
  const ImU32 color = IM_COL32(255, 200, 40, 255);
  draw->PushClipRect({origin.x, origin.y}, {origin.x + regionSize.x, origin.y + regionSize.y}, true);
  ImVec2 corners[4];
  bool all = true;
  const auto world = lightCorners(light);
  for (int i = 0; i < 4; ++i) all = screen(world[size_t(i)], corners[i]) && all;
  if (all) {
    draw->AddConvexPolyFilled(corners, 4, IM_COL32(255, 200, 40, 70));
    draw->AddPolyline(corners, 4, color, ImDrawFlags_Closed, 2);
  }
  if (all) drawLightMask(state, world, screen);
  ImVec2 centre, ground;
  const glm::vec3 forward = glm::normalize(light.forward);
  const float groundY = groundHeight(state.session.scene);
  if (screen(light.center, centre)) {
    draw->AddCircleFilled(centre, 4, color);
    draw->AddText({centre.x + 6, centre.y - 16}, color, "light (Alt+drag)");
    if (forward.y < -1e-3f && light.center.y > groundY) {
      const glm::vec3 hit = light.center + forward * ((groundY - light.center.y) / forward.y);
      if (screen(hit, ground)) {
        draw->AddLine(centre, ground, IM_COL32(255, 200, 40, 160), 1.5f);
        draw->AddCircle(ground, 6, color, 0, 2);
      }
    }
  }
  draw->PopClipRect();
}
