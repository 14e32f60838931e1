#include "scene/gltf_animation.h"

#include <tiny_gltf.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <cstring>
#include <map>

#include "base/input_error.h"

namespace {

class Reader {
 public:
  Reader(const tinygltf::Model& model, const std::string& path) : model_(model), path_(path) {}

  [[noreturn]] void fail(const std::string& pointer, const std::string& what) const {
    throw InputError(path_ + ": " + pointer + ": " + what);
  }

  // The float elements of accessor `index` with `components` each, every byte in range.
  std::vector<float> floats(int index, int type, const std::string& at) const {
    const std::string pointer = at;
    if (index < 0 || static_cast<size_t>(index) >= model_.accessors.size())
      fail(pointer, "accessor " + std::to_string(index) + " out of range (" +
                        std::to_string(model_.accessors.size()) + " accessors)");
    const tinygltf::Accessor& a = model_.accessors[index];
    const std::string where = "/accessors/" + std::to_string(index);
    const int components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(type));
    if (a.type != type)
      fail(where, "keyframe accessor (" + pointer + ") has " +
                      std::to_string(tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type))) +
                      " components per element, expected " + std::to_string(components));
    if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
      fail(where, "keyframe data (" + pointer +
                      ") must be FLOAT (integer-normalized keyframes are not supported)");
    if (a.sparse.isSparse) fail(where, "sparse keyframe accessors are not supported");
    if (a.count == 0) fail(where, "count is 0");
    if (a.bufferView < 0 || static_cast<size_t>(a.bufferView) >= model_.bufferViews.size())
      fail(where, "bufferView " + std::to_string(a.bufferView) + " out of range");
    const tinygltf::BufferView& bv = model_.bufferViews[a.bufferView];
    if (bv.buffer < 0 || static_cast<size_t>(bv.buffer) >= model_.buffers.size())
      fail(where, "bufferView " + std::to_string(a.bufferView) + " refers to a buffer out of range");
    const std::vector<unsigned char>& bytes = model_.buffers[bv.buffer].data;
    if (bv.byteOffset > bytes.size() || bv.byteLength > bytes.size() - bv.byteOffset)
      fail(where, "bufferView " + std::to_string(a.bufferView) + " exceeds its buffer");
    const size_t element = 4 * static_cast<size_t>(components);
    size_t stride = element;
    if (bv.byteStride != 0) {
      if (bv.byteStride < element || bv.byteStride > 252 || bv.byteStride % 4 != 0)
        fail(where, "byteStride " + std::to_string(bv.byteStride) + " invalid");
      stride = bv.byteStride;
    }
    if (a.byteOffset > bv.byteLength || bv.byteLength - a.byteOffset < element ||
        (a.count - 1) > (bv.byteLength - a.byteOffset - element) / stride)
      fail(where, std::to_string(a.count) + " elements exceed bufferView " +
                      std::to_string(a.bufferView));
    std::vector<float> result(a.count * static_cast<size_t>(components));
    const unsigned char* data = bytes.data() + bv.byteOffset + a.byteOffset;
    for (size_t i = 0; i < a.count; ++i)
      std::memcpy(&result[i * components], data + i * stride, element);
    for (size_t i = 0; i < result.size(); ++i)
      if (!std::isfinite(result[i]) || std::abs(result[i]) > 1e30f)
        fail(where, "keyframe value " + std::to_string(i / components) + " (" + pointer +
                        ") is not finite");
    return result;
  }

 private:
  const tinygltf::Model& model_;
  std::string path_;
};

template <class T>
void checkTimes(const Reader& r, const Track<T>& track, const std::string& at) {
  for (size_t i = 0; i < track.times.size(); ++i) {
    if (track.times[i] < 0) r.fail(at, "key " + std::to_string(i) + ": time is negative");
    if (i > 0 && !(track.times[i] > track.times[i - 1]))
      r.fail(at, "key " + std::to_string(i) + ": times must increase (" +
                     std::to_string(track.times[i]) + " is not after " +
                     std::to_string(track.times[i - 1]) + ")");
  }
}

// The rest TRS of a node (the importer has checked its values).
TrsTrack restTrs(const tinygltf::Node& node) {
  TrsTrack trs;
  if (node.translation.size() == 3)
    trs.translation = {node.translation[0], node.translation[1], node.translation[2]};
  if (node.rotation.size() == 4)
    trs.rotation = glm::normalize(
        glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));
  if (node.scale.size() == 3) trs.scale = {node.scale[0], node.scale[1], node.scale[2]};
  return trs;
}

glm::dmat4 restMatrix(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    glm::dmat4 m;
    std::copy(node.matrix.begin(), node.matrix.end(), glm::value_ptr(m));
    return m;
  }
  return restTrs(node).matrixAt(0);
}

}  // namespace

GltfAnimation readGltfAnimation(const tinygltf::Model& model,
                                const std::vector<std::vector<int>>& objectNodePaths,
                                const glm::dmat4& worldFromFile, const std::string& path,
                                std::vector<std::string>& warnings) {
  GltfAnimation result;
  if (model.animations.empty()) return result;
  const Reader r(model, path);
  const tinygltf::Animation& animation = model.animations[0];
  result.name = animation.name;
  if (model.animations.size() > 1)
    warnings.push_back(path + ": " + std::to_string(model.animations.size()) +
                       " animations; only the first ('" + printable(animation.name) +
                       "') is played");

  // The animated nodes and their tracks, the rest values where a channel is absent.
  std::map<int, TrsTrack> animated;
  const std::string at = "/animations/0";
  for (size_t c = 0; c < animation.channels.size(); ++c) {
    const tinygltf::AnimationChannel& channel = animation.channels[c];
    const std::string ch = at + "/channels/" + std::to_string(c);
    const int node = channel.target_node;
    if (node < 0 || static_cast<size_t>(node) >= model.nodes.size())
      r.fail(ch + "/target/node", "node " + std::to_string(node) + " out of range (" +
                                      std::to_string(model.nodes.size()) + " nodes)");
    const std::string& target = channel.target_path;
    if (target == "weights") {
      warnings.push_back(path + ": " + ch + ": morph target weights are not animated (morph "
                                            "targets are ignored)");
      continue;
    }
    if (target != "translation" && target != "rotation" && target != "scale")
      r.fail(ch + "/target/path", "unknown path '" + printable(target) +
                                      "' (valid: translation, rotation, scale, weights)");
    if (model.nodes[node].matrix.size() == 16)
      r.fail(ch + "/target/node", "node " + std::to_string(node) +
                                      " is animated but has a matrix (the spec requires TRS)");
    if (channel.sampler < 0 || static_cast<size_t>(channel.sampler) >= animation.samplers.size())
      r.fail(ch + "/sampler", "sampler " + std::to_string(channel.sampler) + " out of range (" +
                                  std::to_string(animation.samplers.size()) + " samplers)");
    const tinygltf::AnimationSampler& sampler = animation.samplers[channel.sampler];
    const std::string sa = at + "/samplers/" + std::to_string(channel.sampler);
    Interpolation interpolation = Interpolation::Linear;
    if (sampler.interpolation == "STEP")
      interpolation = Interpolation::Step;
    else if (!sampler.interpolation.empty() && sampler.interpolation != "LINEAR")
      r.fail(sa + "/interpolation", "'" + printable(sampler.interpolation) +
                                        "' interpolation is not supported (LINEAR or STEP)");
    const std::vector<float> times = r.floats(sampler.input, TINYGLTF_TYPE_SCALAR, sa + "/input");
    const int type = target == "rotation" ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3;
    const std::vector<float> values = r.floats(sampler.output, type, sa + "/output");
    const size_t width = target == "rotation" ? 4 : 3;
    if (values.size() / width != times.size())
      r.fail(sa + "/output", std::to_string(values.size() / width) + " values for " +
                                 std::to_string(times.size()) + " times (one value per time)");
    auto [entry, isNew] = animated.try_emplace(node, restTrs(model.nodes[node]));
    TrsTrack& trs = entry->second;
    auto fill = [&](auto& track, auto value) {
      if (!track.empty())
        r.fail(ch, "a second " + target + " channel for node " + std::to_string(node));
      track.interpolation = interpolation;
      track.times.assign(times.begin(), times.end());
      for (size_t i = 0; i < times.size(); ++i) track.values.push_back(value(&values[i * width]));
      checkTimes(r, track, sa + "/input");
    };
    if (target == "translation")
      fill(trs.translationKeys, [](const float* v) { return glm::dvec3(v[0], v[1], v[2]); });
    else if (target == "scale")
      fill(trs.scaleKeys, [](const float* v) { return glm::dvec3(v[0], v[1], v[2]); });
    else
      fill(trs.rotationKeys, [&](const float* v) {
        const glm::dquat q(v[3], v[0], v[1], v[2]);  // glTF stores x, y, z, w
        const double length = glm::length(q);
        if (!(length > 1e-6)) r.fail(sa + "/output", "a rotation key has zero length");
        return q / length;
      });
  }
  if (animated.empty()) return result;

  // One motion per object below an animated node:
  //   worldFromFile * N_root(t) * ... * N_leaf(t) * inverse(worldFromFile * rest world).
  for (size_t object = 0; object < objectNodePaths.size(); ++object) {
    const std::vector<int>& nodes = objectNodePaths[object];
    bool moves = false;
    for (int node : nodes) moves = moves || animated.count(node) > 0;
    if (!moves) continue;
    ObjectMotion motion;
    motion.objects.push_back(object);
    ChainLink first;
    first.fixed = worldFromFile;
    motion.chain.push_back(first);
    glm::dmat4 rest = worldFromFile;
    for (int node : nodes) {
      ChainLink link;
      const auto it = animated.find(node);
      if (it != animated.end()) {
        link.animated = true;
        link.trs = it->second;
      } else {
        link.fixed = restMatrix(model.nodes[node]);
      }
      rest = rest * restMatrix(model.nodes[node]);
      motion.chain.push_back(link);
    }
    ChainLink back;
    back.fixed = glm::inverse(rest);  // the importer skipped singular instances
    motion.chain.push_back(back);
    result.motions.push_back(std::move(motion));
  }
  return result;
}

void placeMotion(ObjectMotion& motion, const glm::dmat4& place) {
  ChainLink before, after;
  before.fixed = place;
  after.fixed = glm::inverse(place);
  motion.chain.insert(motion.chain.begin(), before);
  motion.chain.push_back(after);
}
