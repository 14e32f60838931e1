#include "shared_inputs/light/scene_rays.h"

#include <algorithm>
#include <limits>

std::uint64_t& sceneRaysOnThisThread() {
  thread_local std::uint64_t rays = 0;
  return rays;
}

namespace {

// One Embree device for the program's analyses (its threads and allocators outlive each
// scene built on it).
RTCDevice embreeDevice() {
  static RTCDevice device = rtcNewDevice(nullptr);
  return device;
}

}  // namespace

SceneRays::SceneRays(const Scene& source) {
  RTCDevice device = embreeDevice();
  scene = rtcNewScene(device);
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
  for (const SceneObject& object : source.objects) {
    const Mesh& mesh = object.mesh;
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
        std::max<size_t>(mesh.positions.size(), 1)));
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
        mesh.triangleCount()));
    for (size_t i = 0; i < mesh.positions.size(); ++i)
      for (int c = 0; c < 3; ++c) vertices[3 * i + c] = mesh.positions[i][c];
    for (size_t i = 0; i < mesh.indices.size(); ++i) indices[i] = mesh.indices[i];
    rtcCommitGeometry(geometry);
    occluder.push_back(!object.receiverOnly);
    rtcAttachGeometry(scene, geometry);  // ids 0, 1, ... in order
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(scene);
}

SceneRays::~SceneRays() { rtcReleaseScene(scene); }

float SceneRays::hit(const glm::vec3& origin, const glm::vec3& direction, float tNear,
                     unsigned& geometry, glm::vec3* normal) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit query{};
  query.ray.org_x = origin.x; query.ray.org_y = origin.y; query.ray.org_z = origin.z;
  query.ray.dir_x = direction.x; query.ray.dir_y = direction.y; query.ray.dir_z = direction.z;
  query.ray.tnear = tNear;
  query.ray.tfar = std::numeric_limits<float>::infinity();
  query.ray.mask = 0xffffffffu;
  query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene, &context, &query);
  ++sceneRaysOnThisThread();
  geometry = query.hit.geomID;
  if (normal) *normal = glm::vec3(query.hit.Ng_x, query.hit.Ng_y, query.hit.Ng_z);
  return geometry == RTC_INVALID_GEOMETRY_ID ? std::numeric_limits<float>::infinity()
                                             : query.ray.tfar;
}
