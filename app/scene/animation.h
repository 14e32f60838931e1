// Keyframed motion of a scene (docs/design.md#scenes, assets/scenes/README.md "Animation"):
// objects translated, rotated and scaled over time, the light moved, turned and resized.
// A Scene holds its objects at rest and an Animation; poseAt(scene, t) is the static scene
// at time t, the only thing the stages ever see: nothing is precomputed across time, so
// every stage recomputes from the posed geometry as it would for a static scene.
//
// Interpolation, as glTF 2.0 defines it (§3.11 "Animations"): LINEAR interpolates vectors
// and scalars linearly and rotations by spherical linear interpolation along the shorter
// arc (a key 270 degrees after the previous one turns 90 degrees back); STEP holds each
// key's value until the next key. Before the first key a track holds its first value,
// after the last its last value.
#pragma once
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cstddef>
#include <string>
#include <vector>

enum class Interpolation { Linear, Step };

// One animated quantity: times strictly increasing and finite, one value per time.
template <class T>
struct Track {
  std::vector<double> times;
  std::vector<T> values;
  Interpolation interpolation = Interpolation::Linear;
  bool empty() const { return times.empty(); }
  double endTime() const { return times.empty() ? 0 : times.back(); }
};
using ScalarTrack = Track<double>;
using Vec3Track = Track<glm::dvec3>;
using QuatTrack = Track<glm::dquat>;  // unit quaternions

double sampleTrack(const ScalarTrack& track, double t);
glm::dvec3 sampleTrack(const Vec3Track& track, double t);
glm::dquat sampleTrack(const QuatTrack& track, double t);
// Spherical linear interpolation of unit quaternions along the shorter arc (q and -q are
// the same rotation; the one nearer to a is taken).
glm::dquat slerpShorter(const glm::dquat& a, const glm::dquat& b, double u);

// A translation, rotation and scale, each at its rest value or following its track:
// matrix = T * R * S (glTF's order; the scene file's about a pivot, see ObjectMotion).
struct TrsTrack {
  glm::dvec3 translation{0};
  glm::dquat rotation{1, 0, 0, 0};
  glm::dvec3 scale{1};
  Vec3Track translationKeys;
  QuatTrack rotationKeys;
  Vec3Track scaleKeys;
  bool animated() const {
    return !translationKeys.empty() || !rotationKeys.empty() || !scaleKeys.empty();
  }
  double endTime() const;
  glm::dmat4 matrixAt(double t) const;
};

// One link of a transform chain: a fixed matrix, or a TRS that moves.
struct ChainLink {
  glm::dmat4 fixed{1};
  bool animated = false;
  TrsTrack trs;
  glm::dmat4 matrixAt(double t) const { return animated ? trs.matrixAt(t) : fixed; }
};

// A motion of some objects of the scene, applied to their rest meshes (world space):
//   pose(t) = chain[0](t) * chain[1](t) * ... * chain.back()(t)
// A scene file's object: [translate(pivot), TRS(t), translate(-pivot)]. A glTF node:
// [worldFromFile, node TRS from the root down to the mesh's node, inverse(rest world)], so
// the rest mesh is first taken back to the mesh's own space.
struct ObjectMotion {
  std::vector<size_t> objects;  // indices into Scene::objects
  std::vector<ChainLink> chain;
  double endTime() const;
  glm::dmat4 matrixAt(double t) const;
};

// The light's keys: its centre (world space), a rotation of its rest frame (forward and up
// turned about the centre), its width and height.
struct LightMotion {
  Vec3Track center;
  QuatTrack orientation;
  ScalarTrack width, height;
  bool empty() const {
    return center.empty() && orientation.empty() && width.empty() && height.empty();
  }
  double endTime() const;
};

// How time past the duration maps into it.
enum class Repeat { Loop, PingPong, Once };
const char* repeatName(Repeat repeat);  // "loop", "ping_pong", "once"

struct Animation {
  double duration = 0;  // seconds of one cycle; 0 with no tracks
  Repeat repeat = Repeat::Loop;
  std::vector<ObjectMotion> objects;  // applied in this order
  LightMotion light;
  bool empty() const { return objects.empty() && light.empty(); }
  // The last key of every track (the default duration).
  double endTime() const;
  // The time within one cycle: loop wraps, ping-pong runs forward then back, once clamps.
  double cycleTime(double t) const;
};

struct Scene;
// The static scene at time t: every moved object's mesh (positions, normals, winding when
// a transform mirrors) and the light at their poses, the animation removed. A scene
// without animation is returned unchanged. The result can fail validateScene() (a track
// that scales an object to zero, a light turned parallel to its up): posedSceneProblem says so.
Scene poseAt(const Scene& scene, double t);
// "" or the validateScene() problem of the scene at time t, named with the time.
std::string posedSceneProblem(const Scene& scene, double t);
