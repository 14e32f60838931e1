#include "bench/bench_configs.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <cstdio>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/pipeline.h"
#include "scene/light_frame.h"
#include "scene/mesh_builders.h"

namespace {

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  for (std::string part; std::getline(stream, part, separator);)
    if (!part.empty()) parts.push_back(part);
  return parts;
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// --- Configurations ------------------------------------------------------------------

// The sets that make `method` the one shown and measured.
void chooseMethod(BenchConfig& config) {
  config.sets.push_back("composite.shadow=" + config.method);
  config.sets.push_back("error.method=" + config.method);
}

// The Monte Carlo method's lists: a filtered configuration measures `filter`, an
// unfiltered one `trace` (the stages whose outputs carry the shadow-method role).
const std::vector<std::string> kMonteCarloMethods = {"trace", "filter"};

// One Monte Carlo configuration. layers: 1..3; rays: per side. Over the thesis's N-buffer
// (§3.5), so a preset's rows mean the same at every map size.
BenchConfig monteCarlo(const std::string& search, int layers, int rays, int map = 512,
                       bool deferred = true, bool filter = true) {
  const char* layerNames[] = {"", "one", "two", "three"};
  std::string family = (search == "linear_binary" ? std::string("linear/binary") : search) +
                       " " + std::to_string(layers) + "L";
  std::string label = search + " " + std::to_string(layers) + "L " + std::to_string(rays) + "x" +
                      std::to_string(rays);
  if (!deferred) label += " forward", family += " forward";
  if (!filter) label += " unfiltered", family += " unfiltered";
  label += " map " + std::to_string(map);
  BenchConfig config{label, filter ? "filter" : "trace", family,
                     {"trace.search=" + search, "trace.hierarchy=nbuffer",  // the thesis's
                      std::string("light.layers=") + layerNames[layers],
                      "trace.rays=" + std::to_string(rays),
                      std::string("trace.deferred=") + (deferred ? "true" : "false"),
                      std::string("filter.enabled=") + (filter ? "true" : "false"),
                      "light.resolution=" + std::to_string(map)}};
  chooseMethod(config);
  return config;
}

// The graph's methods split into the Monte Carlo ones (when the graph has them all) and
// every other, in registry order.
struct Methods {
  bool monteCarlo = false;
  std::vector<std::string> others;
  // A stage that is off by default (its Bool parameter `enabled`, e.g. raster4d's, which
  // costs seconds per frame on llvmpipe) is switched on where it is measured.
  std::map<std::string, std::string> switchOn;
  // A method with maps of its own (an Int parameter `resolution`, e.g. ssm's occluder,
  // receiver and soft shadow maps) follows the swept map size, as light.resolution does.
  std::set<std::string> ownResolution;
  // A method with variants (an Enum parameter `passes`, e.g. ssm's one and two passes,
  // which Atty et al. 2006 §4.2 compare on every curve): each value, where a preset asks.
  std::map<std::string, std::vector<std::string>> passes;
};

Methods methodsOf(const Pipeline& pipeline) {
  Methods result;
  const std::vector<std::string> all = pipeline.methods();
  auto has = [&](const std::string& m) { return std::find(all.begin(), all.end(), m) != all.end(); };
  result.monteCarlo = std::all_of(kMonteCarloMethods.begin(), kMonteCarloMethods.end(), has);
  for (const std::string& method : all) {
    const bool listed = std::find(kMonteCarloMethods.begin(), kMonteCarloMethods.end(), method) !=
                        kMonteCarloMethods.end();
    if (!(result.monteCarlo && listed)) result.others.push_back(method);
    for (const Param& param : pipeline.stage(method).params()) {
      if (param.key == "enabled" && param.type == Param::Type::Bool && !param.asBool())
        result.switchOn[method] = method + ".enabled=true";
      if (param.key == "resolution" && param.type == Param::Type::Int)
        result.ownResolution.insert(method);
      if (param.key == "passes" && param.type == Param::Type::Enum)
        result.passes[method] = param.options;
    }
  }
  return result;
}

// A method without a list of its own: its declared defaults at shadow-map size `map` (its
// own maps too). everyPass: one configuration per value of its `passes` (family "ssm two
// passes"), else its default only.
std::vector<BenchConfig> withDefaults(const Methods& methods, int map, bool everyPass = false) {
  std::vector<BenchConfig> configs;
  for (const std::string& method : methods.others) {
    BenchConfig config{method + " map " + std::to_string(map), method, method,
                       {"light.resolution=" + std::to_string(map)}};
    if (methods.switchOn.count(method)) config.sets.push_back(methods.switchOn.at(method));
    if (methods.ownResolution.count(method))
      config.sets.push_back(method + ".resolution=" + std::to_string(map));
    chooseMethod(config);
    if (!everyPass || !methods.passes.count(method)) {
      configs.push_back(config);
      continue;
    }
    for (const std::string& passes : methods.passes.at(method)) {
      BenchConfig variant = config;
      const std::string name = method + " " + passes + (passes == "one" ? " pass" : " passes");
      variant.label = name + " map " + std::to_string(map);
      variant.family = name;
      variant.sets.push_back(method + ".passes=" + passes);
      configs.push_back(variant);
    }
  }
  return configs;
}

void append(std::vector<BenchConfig>& to, std::vector<BenchConfig> more) {
  for (BenchConfig& config : more) to.push_back(std::move(config));
}

// The reference as a method on a speed-against-error plot: when is a CPU ray tracer the
// better choice on this machine? 1x1 (a hard shadow from the light's centre) to 8x8.
std::vector<BenchConfig> referenceMethods(bool rebuildBvh = false) {
  std::vector<BenchConfig> configs;
  for (int m : {1, 2, 4, 8}) configs.push_back(referenceConfig(m, rebuildBvh));
  return configs;
}

// The Monte Carlo method as it ships: hierarchical, deferred, filtered, with `auto` choosing
// the map, the layers and the rays (docs/accuracy.md) and the hierarchy
// (docs/decisions/024-minmax-mipmap-levels.md), to be seen against the fixed ones' frontier.
BenchConfig monteCarloAuto() {
  BenchConfig config{"hierarchical auto", "filter", "hierarchical auto",
                     {"trace.search=hierarchical", "trace.hierarchy=auto", "light.layers=auto",
                      "trace.rays=auto", "trace.deferred=true", "filter.enabled=true",
                      "light.resolution=auto"}};
  chooseMethod(config);
  return config;
}

std::vector<BenchConfig> defaultConfigs(const Methods& methods) {
  std::vector<BenchConfig> configs = withDefaults(methods, 512);
  if (methods.monteCarlo) {
    configs.push_back(monteCarloAuto());
    for (int rays = 1; rays <= 4; ++rays) {
      configs.push_back(monteCarlo("linear", 2, rays));
      configs.push_back(monteCarlo("linear_binary", 2, rays));
      configs.push_back(monteCarlo("linear_binary", 3, rays));
      configs.push_back(monteCarlo("hierarchical", 2, rays));
    }
    configs.push_back(monteCarlo("hierarchical", 2, 2, 512, true, false));
    configs.push_back(monteCarlo("hierarchical", 2, 2, 512, false, true));
    for (int map : {128, 256, 1024}) configs.push_back(monteCarlo("hierarchical", 2, 2, map));
  }
  for (int map : {128, 1024}) append(configs, withDefaults(methods, map));
  append(configs, referenceMethods());
  return configs;
}

std::vector<BenchConfig> minimalConfigs(const Methods& methods) {
  std::vector<BenchConfig> configs = withDefaults(methods, 512);
  if (methods.monteCarlo) configs.push_back(monteCarlo("hierarchical", 2, 2));
  append(configs, referenceMethods());
  return configs;
}

// Wang et al. §5 compare 4D rasterization with a ray tracer at the same 32 x 32 uniform light
// samples, which on their dynamic Toys "has to recompute the BVH for every frame": every
// method at its defaults (raster4d at 32 x 32), Monte Carlo as it ships and at 2x2, and the
// reference rebuilding its BVH each frame at 1x1 .. 8x8 and at 32 x 32.
std::vector<BenchConfig> animatedConfigs(const Methods& methods) {
  std::vector<BenchConfig> configs = withDefaults(methods, 512);
  if (methods.monteCarlo) {
    configs.push_back(monteCarloAuto());
    configs.push_back(monteCarlo("hierarchical", 2, 2));
  }
  append(configs, referenceMethods(/*rebuildBvh=*/true));
  configs.push_back(referenceConfig(32, /*rebuildBvh=*/true));
  return configs;
}

// The thesis's rows (Tables 4.1-4.4): hierarchical with two layers (deferred and
// forward), linear/binary with three layers (deferred), at 2x2 and 3x3 rays.
std::vector<BenchConfig> thesisRows(const Methods& methods, int map) {
  if (!methods.monteCarlo) return {};
  return {monteCarlo("hierarchical", 2, 2, map), monteCarlo("hierarchical", 2, 3, map),
          monteCarlo("hierarchical", 2, 2, map, false), monteCarlo("hierarchical", 2, 3, map, false),
          monteCarlo("linear_binary", 3, 2, map), monteCarlo("linear_binary", 3, 3, map)};
}

// Atty et al. compare their one- and two-pass versions (ssm: both); the Monte Carlo
// method's analogues are one and two depth layers, with the other methods (the hard
// shadow, PCSS, ...) and three layers (linear/binary) next to them.
std::vector<BenchConfig> attyMethods(const Methods& methods, int map) {
  std::vector<BenchConfig> configs = withDefaults(methods, map, /*everyPass=*/true);
  if (methods.monteCarlo)
    append(configs, {monteCarlo("hierarchical", 1, 2, map), monteCarlo("hierarchical", 2, 2, map),
                     monteCarlo("linear_binary", 3, 2, map)});
  return configs;
}

// --- Scene modifiers -----------------------------------------------------------------

Bounds occluderBounds(const Scene& scene) { return scene.bounds(/*occludersOnly=*/true); }

void translateOccluders(Scene& scene, const glm::vec3& offset) {
  const glm::mat4 move = glm::translate(glm::mat4(1), offset);
  for (SceneObject& object : scene.objects)
    if (!object.receiverOnly) transformMesh(object.mesh, move);
}

LightFrame lightFrameOf(const Scene& scene) { return computeLightFrame(scene.light, scene.bounds(), 90); }

// Half the extent of the occluders' box along a unit direction.
float halfExtentAlong(const Bounds& bounds, const glm::vec3& direction) {
  const glm::vec3 half = 0.5f * (bounds.max - bounds.min);
  return glm::dot(half, glm::abs(direction));
}

BenchSetup makeSetup(const Scene& scene, int width, int height, std::vector<BenchConfig> configs,
                     const std::string& axis = "", double value = 0) {
  BenchSetup setup;
  setup.scene = scene;
  setup.width = width;
  setup.height = height;
  setup.configs = std::move(configs);
  setup.axis = axis;
  setup.axisValue = value;
  setup.label = scene.name + " " + std::to_string(width) + "x" + std::to_string(height);
  if (!axis.empty()) setup.label += " " + axis + "=" + number(value);
  return setup;
}

// Applies one setup axis to a copy of `setup` (the label says which value).
BenchSetup withAxis(const BenchSetup& setup, const std::string& axis, const std::string& value) {
  BenchSetup result = setup;
  if (axis == "eye.size") {
    const auto parts = split(value, 'x');
    if (parts.size() != 2) throw std::invalid_argument("eye.size values are WxH, e.g. 256x256");
    result.width = std::stoi(parts[0]);
    result.height = std::stoi(parts[1]);
    if (result.width < 16 || result.height < 16 || result.width > 4096 || result.height > 4096)
      throw std::invalid_argument("eye.size must be within 16..4096 on each side");
    result.label = setup.scene.name + " " + value;
    return result;
  }
  const double v = std::stod(value);
  if (axis == "scene.light_scale") {
    if (!(v > 0)) throw std::invalid_argument("scene.light_scale must be > 0");
    scaleLight(result.scene, v);
  } else if (axis == "scene.lateral") {
    placeOccludersLaterally(result.scene, v);
  } else if (axis == "scene.vertical") {
    if (v < 0 || v > 1) throw std::invalid_argument("scene.vertical must be within [0, 1]");
    placeOccludersVertically(result.scene, v);
  } else {
    throw std::invalid_argument("unknown setup axis '" + axis + "'");
  }
  result.axis = axis.substr(axis.find('.') + 1);
  result.axisValue = v;
  result.label = setup.label + " " + result.axis + "=" + number(v);
  return result;
}

bool isSetupAxis(const std::string& key) {
  return key == "eye.size" || key == "scene.light_scale" || key == "scene.lateral" ||
         key == "scene.vertical";
}

}  // namespace

BenchConfig referenceConfig(int samples, bool rebuildBvh) {
  const std::string m = std::to_string(samples);
  BenchConfig config{"reference " + m + "x" + m + (rebuildBvh ? " BVH rebuilt" : ""), "reference",
                     "reference", {}, samples, rebuildBvh};
  return config;
}

std::vector<double> loopTimes(double start, double cycle, double fps, int limit) {
  const int whole = std::max(1, int(std::lround(cycle * fps)));
  const int count = limit > 0 ? std::min(limit, whole) : whole;
  std::vector<double> times;
  for (int i = 0; i < count; ++i) times.push_back(start + double(i) / fps);
  return times;
}

void scaleLight(Scene& scene, double factor) {
  scene.light.width *= float(factor);
  scene.light.height *= float(factor);
}

void placeOccludersLaterally(Scene& scene, double lightWidths) {
  const Bounds bounds = occluderBounds(scene);
  if (bounds.empty()) return;
  const LightFrame frame = lightFrameOf(scene);
  const glm::vec3 centre = 0.5f * (bounds.min + bounds.max);
  const glm::vec3 fromLight = centre - scene.light.center;
  const float depth = glm::dot(fromLight, frame.forward);
  const glm::vec3 target = scene.light.center + depth * frame.forward +
                           float(lightWidths) * scene.light.width * frame.right;
  translateOccluders(scene, target - centre);
}

void placeOccludersVertically(Scene& scene, double t) {
  const Bounds bounds = occluderBounds(scene);
  if (bounds.empty()) return;
  const LightFrame frame = lightFrameOf(scene);
  const glm::vec3 centre = 0.5f * (bounds.min + bounds.max);
  // The receivers' depth along the light axis: where the axis through the occluders'
  // centre meets a receiver-only triangle (the ground), else the scene's far end.
  const float currentDepth = glm::dot(centre - scene.light.center, frame.forward);
  float receiverDepth = currentDepth + glm::length(scene.bounds().max - scene.bounds().min);
  for (const SceneObject& object : scene.objects) {
    if (!object.receiverOnly) continue;
    const Mesh& mesh = object.mesh;
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
      const glm::vec3 a = mesh.positions[mesh.indices[i]], b = mesh.positions[mesh.indices[i + 1]],
                      c = mesh.positions[mesh.indices[i + 2]];
      const glm::vec3 e1 = b - a, e2 = c - a, q = glm::cross(frame.forward, e2);
      const float det = glm::dot(e1, q);
      if (std::abs(det) < 1e-12f) continue;
      const glm::vec3 s = centre - a;
      const float u = glm::dot(s, q) / det;
      const glm::vec3 r = glm::cross(s, e1);
      const float v = glm::dot(frame.forward, r) / det, hit = glm::dot(e2, r) / det;
      if (u >= 0 && v >= 0 && u + v <= 1 && hit > 0)
        receiverDepth = std::min(receiverDepth, currentDepth + hit);
    }
  }
  const float half = halfExtentAlong(bounds, frame.forward);
  const float nearest = half, farthest = std::max(half, receiverDepth - half);
  const float depth = float(1 - t) * farthest + float(t) * nearest;
  translateOccluders(scene, (depth - currentDepth) * frame.forward);
}

std::vector<std::string> benchPresetNames() {
  return {"default", "minimal", "thesis-table-4.1", "atty-4.2", "animated"};
}

std::vector<BenchSetup> makeBenchPlan(const Scene& scene, const BenchPlanOptions& options,
                                      const Pipeline& pipeline) {
  const Methods methods = methodsOf(pipeline);
  const std::string preset = options.preset.empty() ? "default" : options.preset;
  std::vector<BenchSetup> setups;
  int w = options.width, h = options.height;
  if (preset == "default" || preset == "minimal") {
    if (w == 0) w = 256;
    if (h == 0) h = 256;
    setups.push_back(makeSetup(scene, w, h, preset == "default" ? defaultConfigs(methods)
                                                                : minimalConfigs(methods)));
  } else if (preset == "thesis-table-4.1") {
    if (w == 0) w = 512;
    if (h == 0) h = 384;
    std::vector<BenchConfig> configs = withDefaults(methods, 512);
    for (int map : {256, 512, 1024}) append(configs, thesisRows(methods, map));
    append(configs, referenceMethods());
    setups.push_back(makeSetup(scene, w, h, configs));
    // Tables 4.3/4.4: 800x600 and 1280x1024 at the same scale (1024x768 is the main setup).
    const double scale = double(w) / 1024.0;
    for (const glm::ivec2 size : {glm::ivec2(800, 600), glm::ivec2(1280, 1024)})
      setups.push_back(makeSetup(scene, int(std::lround(size.x * scale)),
                                 int(std::lround(size.y * scale)), thesisRows(methods, 512)));
  } else if (preset == "atty-4.2") {
    if (w == 0) w = 256;
    if (h == 0) h = 256;
    std::vector<BenchConfig> maps;
    for (int map : {128, 192, 256, 384, 512, 768, 1024})
      append(maps, attyMethods(methods, map));
    append(maps, referenceMethods());  // on the map sweep's speed-against-error plot
    setups.push_back(makeSetup(scene, w, h, maps, "map", 0));
    setups.back().label = scene.name + " " + std::to_string(w) + "x" + std::to_string(h) + " map sweep";
    const BenchSetup base = makeSetup(scene, w, h, attyMethods(methods, 128));
    for (const char* v : {"0.05", "0.25", "0.5", "1", "1.5", "2"})
      setups.push_back(withAxis(base, "scene.light_scale", v));
    for (const char* v : {"-1", "-0.5", "-0.25", "0", "0.25", "0.5", "1"})
      setups.push_back(withAxis(base, "scene.lateral", v));
    for (const char* v : {"0.02", "0.25", "0.5", "0.75", "0.98"})
      setups.push_back(withAxis(base, "scene.vertical", v));
    // The paper's metric counts the receivers only (§4.2.1): soft shadow maps compute no
    // self-shadowing (§3), so an occluder's own surface is no part of what they measure.
    for (BenchSetup& setup : setups)
      for (BenchConfig& config : setup.configs) config.sets.push_back("error.pixels=receivers");
  } else if (preset == "animated") {
    if (scene.animation.empty())
      throw std::invalid_argument("preset animated needs an animated scene ('" + scene.name +
                                  "' has no animation): dragon_turntable, light_sweep, toys, or "
                                  "a scene file with an \"animation\"");
    if (!(options.fps > 0 && options.fps <= 240)) throw std::invalid_argument("--fps must be within (0, 240]");
    if (w == 0) w = 160;
    if (h == 0) h = 120;
    // One whole cycle: ping-pong runs forward and back (scene/animation.h).
    const double cycle = scene.animation.duration *
                         (scene.animation.repeat == Repeat::PingPong ? 2.0 : 1.0);
    BenchSetup setup = makeSetup(poseAt(scene, options.time), w, h, animatedConfigs(methods));
    setup.rest = std::make_shared<const Scene>(scene);
    setup.loopTimes = loopTimes(options.time, cycle, options.fps, options.loopFrames);
    setup.fps = options.fps;
    setup.cycle = cycle;
    setup.label = scene.name + " " + std::to_string(w) + "x" + std::to_string(h) + " loop";
    setups.push_back(std::move(setup));
  } else {
    std::string valid;
    for (const std::string& name : benchPresetNames()) valid += (valid.empty() ? "" : ", ") + name;
    throw std::invalid_argument("unknown preset '" + preset + "'; valid: " + valid);
  }

  // Stages that some method's visibility depends on: a parameter of one of them leaves the
  // methods that do not depend on it unchanged (trace.rays and a hard shadow), so those are
  // not repeated; parameters of other stages (composite, error) repeat every configuration.
  std::set<std::string> methodStages;
  for (const std::string& method : pipeline.methods())
    for (const std::string& stage : pipeline.dependencies({pipeline.methodOutput(method)}))
      methodStages.insert(stage);
  for (const std::string& sweep : options.sweeps) {
    const size_t equals = sweep.find('=');
    if (equals == std::string::npos || equals == 0)
      throw std::invalid_argument("--sweep '" + sweep + "' is not KEY=v1,v2,...");
    const std::string key = sweep.substr(0, equals);
    const std::vector<std::string> values = split(sweep.substr(equals + 1), ',');
    if (values.empty()) throw std::invalid_argument("--sweep '" + sweep + "' has no values");
    if (isSetupAxis(key)) {
      std::vector<BenchSetup> expanded;
      for (const BenchSetup& setup : setups) {
        if (setup.animated())
          throw std::invalid_argument("--sweep " + key + " does not apply to preset animated "
                                      "(it would change only the first frame's pose)");
        for (const std::string& value : values) expanded.push_back(withAxis(setup, key, value));
      }
      setups = std::move(expanded);
    } else {
      const std::string stage = key.substr(0, key.find('.'));
      for (BenchSetup& setup : setups) {
        std::vector<BenchConfig> expanded;
        for (const BenchConfig& config : setup.configs) {
          if (config.referenceSamples > 0) {  // no stage of the graph is its visibility
            expanded.push_back(config);
            continue;
          }
          const auto closure = pipeline.dependencies({pipeline.methodOutput(config.method)});
          const bool unused = methodStages.count(stage) &&
                              std::find(closure.begin(), closure.end(), stage) == closure.end();
          if (unused) {
            expanded.push_back(config);
            continue;
          }
          for (const std::string& value : values) {
            BenchConfig swept = config;
            swept.sets.push_back(key + "=" + value);
            swept.label += " " + key + "=" + value;
            expanded.push_back(std::move(swept));
          }
        }
        setup.configs = std::move(expanded);
      }
    }
  }
  // A graph without the Monte Carlo method leaves the thesis's eye-size setups empty.
  setups.erase(std::remove_if(setups.begin(), setups.end(),
                              [](const BenchSetup& setup) { return setup.configs.empty(); }),
               setups.end());
  return setups;
}
