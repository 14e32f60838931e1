#include "support/analytic_scenes.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>

#include "scene/mesh_builders.h"
#include "support/gl_test.h"

namespace {

SceneObject groundOf(float size) {
  return {"ground", makeQuad(size, glm::mat4(1)), glm::vec3(0.85f), true};
}

SceneObject plateAt(const std::string& name, float size, const glm::mat4& place) {
  return {name, makeQuad(size, place), {0.3f, 0.5f, 0.9f}, false};
}

glm::mat4 at(const glm::vec3& position) { return glm::translate(glm::mat4(1), position); }

}  // namespace

std::vector<std::string> analyticSceneNames() {
  return {"plate_mid", "plate_contact", "tilted_plate", "box",
          "stacked_plates", "large_light", "tiny_light", "huge_ground"};
}

Scene makeAnalyticScene(const std::string& name) {
  Scene scene;
  scene.name = name;
  scene.light = {{0, 3, 0}, {0, -1, 0}, {0, 0, -1}, 1.0f, 1.0f};
  scene.camera = {{0, 3.5f, 4.5f}, {0, 0.2f, 0}, {0, 1, 0}, 45};
  scene.objects.push_back(groundOf(12));
  if (name == "plate_mid") {
    scene.objects.push_back(plateAt("plate", 1, at({0, 1, 0})));
  } else if (name == "plate_contact") {  // Atty 2006 §4.2's contact case
    scene.objects.push_back(plateAt("plate", 1, at({0, 0.06f, 0})));
  } else if (name == "tilted_plate") {
    scene.objects.push_back(
        plateAt("plate", 1.2f, glm::rotate(at({0, 1, 0}), glm::radians(35.0f), {1, 0, 0})));
  } else if (name == "box") {
    glm::mat4 place = glm::rotate(at({0, 0.6f, 0}), glm::radians(20.0f), {0, 1, 0});
    scene.objects.push_back({"box", makeBox({0.8f, 0.4f, 0.6f}, place), {0.9f, 0.35f, 0.25f}, false});
  } else if (name == "stacked_plates") {
    scene.objects.push_back(plateAt("upper", 0.8f, at({-0.25f, 1.6f, 0})));
    scene.objects.push_back(plateAt("lower", 0.8f, at({0.3f, 0.8f, 0.1f})));
  } else if (name == "large_light") {
    scene.objects.push_back(plateAt("plate", 1, at({0, 1, 0})));
    scene.light.width = scene.light.height = 3.0f;
  } else if (name == "tiny_light") {
    scene.objects.push_back(plateAt("plate", 1, at({0, 1, 0})));
    scene.light.width = scene.light.height = 0.05f;
  } else if (name == "huge_ground") {  // docs/accuracy.md defects 1 and 2: a 1000-unit ground
    scene.objects[0] = groundOf(1000);
    scene.objects.push_back(plateAt("plate", 1, at({0, 0.06f, 0})));
  } else {
    throw std::invalid_argument("unknown analytic scene '" + name + "'");
  }
  return scene;
}

std::vector<double> analyticImage(const PipelineRun& run) {
  const std::vector<float> positions = run.read("gbuffer.wsPosition");
  const std::vector<float> normals = run.read("gbuffer.wsNormal");
  const AnalyticLight light = analyticLight(run.scene.light);
  const std::vector<ConvexPolygon> occluders = occluderTriangles(run.scene);
  std::vector<double> exact(positions.size() / 4, -1.0);
  for (size_t i = 0; i < exact.size(); ++i) {
    if (positions[4 * i + 3] == 0) continue;
    const glm::dvec3 p{positions[4 * i], positions[4 * i + 1], positions[4 * i + 2]};
    const glm::dvec3 n = glm::normalize(glm::dvec3(normals[4 * i], normals[4 * i + 1], normals[4 * i + 2]));
    // The G-buffer's point is float: on an occluder (a plate's top) it may lie a rounding
    // step behind the surface, which would then hide the light. It is moved off the surface
    // by far more than that rounding (1e-5 x its largest coordinate, at least 1e-5).
    const double offset = 1e-5 * std::max({1.0, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
    exact[i] = analyticVisibility(light, occluders, p + offset * n, n);
  }
  return exact;
}

AnalyticError compareWithAnalytic(const std::vector<float>& method,
                                  const std::vector<double>& exact) {
  // One value per pixel in both: a size mismatch means the wrong output or image size, and
  // comparing a prefix would hide it.
  if (method.size() != exact.size())
    throw std::invalid_argument("compareWithAnalytic: " + std::to_string(method.size()) +
                                " method values for " + std::to_string(exact.size()) + " pixels");
  AnalyticError e;
  double umbraSum = 0;
  for (size_t i = 0; i < exact.size(); ++i) {
    if (exact[i] < 0) continue;
    const double value = method[i];
    if (!std::isfinite(value) || value < 0 || value > 1) ++e.outOfRange;
    if (exact[i] >= 1 - 1e-9) continue;
    const double error = value - exact[i];
    e.meanAbsInShadow += std::fabs(error);
    e.meanSigned += error;
    e.maxAbs = std::max(e.maxAbs, std::fabs(error));
    ++e.pixelsInShadow;
    if (exact[i] < 0.1) {
      umbraSum += error;
      ++e.pixelsInUmbra;
    }
  }
  if (e.pixelsInShadow) {
    e.meanAbsInShadow /= double(e.pixelsInShadow);
    e.meanSigned /= double(e.pixelsInShadow);
  }
  if (e.pixelsInUmbra) e.meanInUmbra = umbraSum / double(e.pixelsInUmbra);
  return e;
}
