#include "shared_inputs/light/auto_frustum.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/glm.hpp>

namespace {

double tanHalf(double degrees) { return std::tan(0.5 * degrees * M_PI / 180.0); }
double degreesOfTanHalf(double t) { return 2.0 * std::atan(t) * 180.0 / M_PI; }

// The fov of the longer side for tangents t_x, t_y across width and height (Eq 3.1's shape:
// lightDepth = min(w / 2t_x, h / 2t_y)).
double fovFor(double tanX, double tanY, double w, double h) {
  const double depth = std::min(tanX > 0 ? 0.5 * w / tanX : INFINITY,
                                tanY > 0 ? 0.5 * h / tanY : INFINITY);
  if (!std::isfinite(depth)) return 0;
  return degreesOfTanHalf(0.5 * std::max(w, h) / depth);
}

}  // namespace

std::string quotedNames(const std::vector<std::string>& list) {
  std::string out;
  for (size_t i = 0; i < list.size() && i < 6; ++i) out += (i ? ", '" : "'") + list[i] + "'";
  if (list.size() > 6) out += " and " + std::to_string(list.size() - 6) + " more";
  return out;
}

FrustumFit fitLightFrustum(const Scene& scene, double maxDegrees) {
  FrustumFit fit;
  const AreaLight& light = scene.light;
  // The light's frame as scene/light_frame.cpp builds it.
  const glm::vec3 forward = glm::normalize(light.forward);
  const glm::vec3 right = glm::normalize(glm::cross(forward, light.up));
  const glm::vec3 up = glm::cross(right, forward);
  const double w = light.width, h = light.height, longest = std::max(w, h);
  // The most any frustum of Eq 3.1's shape reaches at maxDegrees.
  const double depthAtMax = 0.5 * longest / tanHalf(maxDegrees);
  const double maxTanX = 0.5 * w / depthAtMax, maxTanY = 0.5 * h / depthAtMax;
  const double scale = std::max({1.0, double(glm::length(light.center)), longest});
  std::vector<std::string> behind, tooWide;
  for (const SceneObject& object : scene.objects) {
    if (object.receiverOnly) continue;
    bool anyInFront = false, anyBehind = false, anyTooWide = false;
    for (const glm::vec3& p : object.mesh.positions) {
      const glm::dvec3 d = glm::dvec3(p) - glm::dvec3(light.center);
      const double x = glm::dot(d, glm::dvec3(right)), y = glm::dot(d, glm::dvec3(up));
      const double z = glm::dot(d, glm::dvec3(forward));
      if (z <= 1e-6 * scale) {
        anyBehind = true;
        continue;
      }
      anyInFront = true;
      const double tx = (std::fabs(x) + 0.5 * w) / z, ty = (std::fabs(y) + 0.5 * h) / z;
      if (tx > maxTanX || ty > maxTanY) {
        anyTooWide = true;
        continue;
      }
      fit.neededTanX = std::max(fit.neededTanX, tx);
      fit.neededTanY = std::max(fit.neededTanY, ty);
    }
    // Wholly behind the light plane: the light (one-sided, facing forward) sends it no light
    // to block; nothing to cover.
    if (anyBehind && anyInFront) behind.push_back(object.name);
    else if (anyTooWide) tooWide.push_back(object.name);
  }
  fit.neededDegrees = fovFor(fit.neededTanX, fit.neededTanY, w, h);
  // Within rounding of the floor (a caster exactly on the 90-degree cone): the floor itself.
  fit.fovDegrees = fit.neededDegrees <= kAutoFovFloorDegrees + 1e-6
                       ? kAutoFovFloorDegrees
                       : std::min(fit.neededDegrees, maxDegrees);
  char text[512];
  if (fit.fovDegrees <= kAutoFovFloorDegrees)
    std::snprintf(text, sizeof text,
                  "fov %.0f: every caster's shadow, from every point of the light, lies inside "
                  "the light's frustum at %.0f degrees (the casters need %.1f)",
                  fit.fovDegrees, kAutoFovFloorDegrees, fit.neededDegrees);
  else
    std::snprintf(text, sizeof text,
                  "fov %.1f, not %.0f: so that every caster's shadow, from every point of the "
                  "light, lies inside the light's frustum (a caster seen from the light's far "
                  "edge at tan %.3g across, %.3g along)",
                  fit.fovDegrees, kAutoFovFloorDegrees, fit.neededTanX, fit.neededTanY);
  fit.reason = text;
  fit.uncovered = behind;
  fit.uncovered.insert(fit.uncovered.end(), tooWide.begin(), tooWide.end());
  std::string warning;
  if (!behind.empty())
    warning += "caster " + quotedNames(behind) +
               " reaches through the light's plane: its part next to the plane shadows "
               "receivers outside any light frustum, which read as lit there";
  if (!tooWide.empty())
    warning += std::string(warning.empty() ? "" : "; ") + "caster " + quotedNames(tooWide) +
               " would need a field of view over " + std::to_string(int(maxDegrees)) +
               " degrees: receivers it shadows outside the light's frustum read as lit";
  if (!warning.empty()) fit.warning = "WARNING: " + warning + " (docs/decisions/135)";
  return fit;
}

std::string fixedFovWarning(const FrustumFit& fit, double fixedDegrees) {
  std::string warning = fit.warning;
  if (fit.neededDegrees > fixedDegrees + 1e-6) {
    char text[320];
    std::snprintf(text, sizeof text,
                  "WARNING: light.fov_degrees=%.1f is narrower than the %.1f the casters need: "
                  "receivers shadowed outside the light's frustum read as lit (light.fov_degrees"
                  "=auto fits it)",
                  fixedDegrees, fit.neededDegrees);
    warning = warning.empty() ? text : warning + "; " + text;
  }
  return warning;
}
