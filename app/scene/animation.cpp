#include "scene/animation.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "scene/mesh_normals.h"
#include "scene/scene.h"

namespace {

// The key interval holding t: i with times[i] <= t < times[i+1], and the fraction u of the
// way from key i to key i+1. Clamped to the first and last keys.
struct Segment {
  size_t i = 0;
  double u = 0;
  bool single = true;  // only key i counts (outside the keys, or one key)
};

template <class T>
Segment segment(const Track<T>& track, double t) {
  const std::vector<double>& times = track.times;
  if (times.size() < 2 || !(t > times.front())) return {0, 0, true};
  if (t >= times.back()) return {times.size() - 1, 0, true};
  // The first key after t; times are strictly increasing (the readers check).
  const size_t next = static_cast<size_t>(std::upper_bound(times.begin(), times.end(), t) -
                                          times.begin());
  const size_t i = next - 1;
  if (track.interpolation == Interpolation::Step) return {i, 0, true};
  return {i, (t - times[i]) / (times[next] - times[i]), false};
}

}  // namespace

glm::dquat slerpShorter(const glm::dquat& a, glm::dquat const& bIn, double u) {
  glm::dquat b = bIn;
  double cosine = glm::dot(a, b);
  if (cosine < 0) {  // -b is the same rotation, nearer to a
    b = -b;
    cosine = -cosine;
  }
  if (cosine > 1 - 1e-12) return glm::normalize(a * (1 - u) + b * u);  // (nearly) equal
  const double angle = std::acos(std::min(cosine, 1.0));
  const double s = std::sin(angle);
  return a * (std::sin((1 - u) * angle) / s) + b * (std::sin(u * angle) / s);
}

double sampleTrack(const ScalarTrack& track, double t) {
  const Segment s = segment(track, t);
  if (s.single) return track.values[s.i];
  return track.values[s.i] + (track.values[s.i + 1] - track.values[s.i]) * s.u;
}

glm::dvec3 sampleTrack(const Vec3Track& track, double t) {
  const Segment s = segment(track, t);
  if (s.single) return track.values[s.i];
  return track.values[s.i] + (track.values[s.i + 1] - track.values[s.i]) * s.u;
}

glm::dquat sampleTrack(const QuatTrack& track, double t) {
  const Segment s = segment(track, t);
  if (s.single) return track.values[s.i];
  return slerpShorter(track.values[s.i], track.values[s.i + 1], s.u);
}

double TrsTrack::endTime() const {
  return std::max({translationKeys.endTime(), rotationKeys.endTime(), scaleKeys.endTime()});
}

glm::dmat4 TrsTrack::matrixAt(double t) const {
  const glm::dvec3 tr = translationKeys.empty() ? translation : sampleTrack(translationKeys, t);
  const glm::dquat r = rotationKeys.empty() ? rotation : sampleTrack(rotationKeys, t);
  const glm::dvec3 s = scaleKeys.empty() ? scale : sampleTrack(scaleKeys, t);
  glm::dmat4 m = glm::translate(glm::dmat4(1), tr);
  m = m * glm::mat4_cast(glm::normalize(r));
  return glm::scale(m, s);
}

double ObjectMotion::endTime() const {
  double end = 0;
  for (const ChainLink& link : chain)
    if (link.animated) end = std::max(end, link.trs.endTime());
  return end;
}

glm::dmat4 ObjectMotion::matrixAt(double t) const {
  glm::dmat4 m(1);
  for (const ChainLink& link : chain) m = m * link.matrixAt(t);
  return m;
}

double LightMotion::endTime() const {
  return std::max({center.endTime(), orientation.endTime(), width.endTime(), height.endTime()});
}

const char* repeatName(Repeat repeat) {
  switch (repeat) {
    case Repeat::Loop: return "loop";
    case Repeat::PingPong: return "ping_pong";
    case Repeat::Once: return "once";
  }
  return "loop";
}

double Animation::endTime() const {
  double end = light.endTime();
  for (const ObjectMotion& motion : objects) end = std::max(end, motion.endTime());
  return end;
}

double Animation::cycleTime(double t) const {
  if (!(duration > 0) || !std::isfinite(t)) return 0;
  switch (repeat) {
    case Repeat::Once: return std::clamp(t, 0.0, duration);
    case Repeat::Loop: {
      const double c = std::fmod(t, duration);
      return c < 0 ? c + duration : c;
    }
    case Repeat::PingPong: {
      double c = std::fmod(t, 2 * duration);
      if (c < 0) c += 2 * duration;
      return c <= duration ? c : 2 * duration - c;
    }
  }
  return 0;
}

namespace {

bool isIdentity(const glm::dmat4& m) { return m == glm::dmat4(1); }

}  // namespace

Scene poseAt(const Scene& scene, double time) {
  Scene posed = scene;
  const Animation& animation = scene.animation;
  posed.animation = Animation{};
  posed.time = time;
  if (animation.empty()) return posed;
  const double t = animation.cycleTime(time);
  // One matrix per object, the motions composed in their order.
  std::vector<glm::dmat4> pose(scene.objects.size(), glm::dmat4(1));
  for (const ObjectMotion& motion : animation.objects) {
    const glm::dmat4 m = motion.matrixAt(t);
    for (size_t object : motion.objects)
      if (object < pose.size()) pose[object] = m * pose[object];
  }
  for (size_t i = 0; i < pose.size(); ++i)
    if (!isIdentity(pose[i])) transformMesh(posed.objects[i].mesh, pose[i]);

  const LightMotion& light = animation.light;
  AreaLight& out = posed.light;
  if (!light.center.empty()) out.center = glm::vec3(sampleTrack(light.center, t));
  if (!light.orientation.empty()) {
    const glm::dquat q = glm::normalize(sampleTrack(light.orientation, t));
    out.forward = glm::vec3(glm::normalize(q * glm::dvec3(scene.light.forward)));
    out.up = glm::vec3(glm::normalize(q * glm::dvec3(scene.light.up)));
  }
  if (!light.width.empty()) out.width = static_cast<float>(sampleTrack(light.width, t));
  if (!light.height.empty()) out.height = static_cast<float>(sampleTrack(light.height, t));
  return posed;
}

std::string posedSceneProblem(const Scene& scene, double t) {
  const std::string problem = validateScene(poseAt(scene, t));
  if (problem.empty()) return "";
  char at[64];
  std::snprintf(at, sizeof at, "at time %g: ", t);
  return at + problem;
}
