// Stage `light` (thesis §3, Eq 3.1 and Eq 3.2): the light as every later stage sees it. It
// owns what the depth-map stages share, declared once: the light's frustum (projection
// point behind the light's centre, field of view, map resolution), the bias group of Eq 3.2,
// the number of depth layers that model the occluders (§3.2-3.4, read by classification and
// the trace) and the hash that picks light samples (§3.1, Appendix A). Its output is the uniform block
// of shaders/shared/light_block.h; a CPU copy goes to frame.light for the CPU-side readers; what `auto` chose stays with this stage
// (lightAutoSettings()).
#include "shared_inputs/light/auto_frustum.h"
#include "shared_inputs/light/auto_params.h"

#include <cstdio>
#include <string>
#include "core/frame.h"
#include "core/pipeline.h"
#include "gl/gpu_layout.h"
#include "gl/hash_kind.h"

namespace {

// light.fov_degrees: `auto` (the default) or a fixed angle.
Param fovParam() {
  Param fov = Param::real(
      "fov_degrees",
      "Field of view of the light's frustum (Eq 3.1), across the light's longer side. Wider "
      "covers more of the scene at lower resolution; the light's projection point moves "
      "closer. auto (the default): 90, or wider where a caster's shadow, seen from any point "
      "of the light (its far edge), would leave the frustum: receivers outside it read as lit "
      "(decision 009); at most 150. Casters that no frustum covers (reaching through the "
      "light's plane) are named in a warning (stages/shared_inputs/light/auto_frustum.h, decision 135).",
      kAutoFovFloorDegrees, 10, 150);
  fov.allowsAuto = fov.automatic = true;
  return fov;
}

class LightStage final : public Stage {
public:
  LightStage() {
    outputs_ = {Output::buffer("light", "The light frame (Eq 3.1), the map size, the Eq 3.2 "
                                        "bias group and the sample hash, as the uniform block "
                                        "of shaders/shared/light_block.h.")};
    params_ = {
        Param::integerOrAuto(
            "resolution",
            "Shadow-map size in texels (square): the light layers, the N-buffer and every "
            "depth-map method's maps. auto (the default): so that 98% of the penumbra area in "
            "view spans 6 texels, but no larger than the map whose build costs what the trace "
            "does unless the narrow penumbrae hold half the shadow (a contact shadow), in "
            "[256, 2048], at least 256 x tan(fov/2) at a frustum wider than 90 degrees, so "
            "that the normal offset's lift moves a penumbra by at most 5% of its width, and so "
            "that a steep occluder (a sheet nearly edge-on to the light) spans 12 texels across "
            "its image (stages/shared_inputs/light/auto_settings.h, occluder_image.h; the "
            "choice and its reasons: the auto.* "
            "counters and the inspector). The limit of every "
            "depth-map method (thesis §4.1, Atty 2006 §4.2): a penumbra narrower than a few "
            "texels is lost. A plate 0.06 above the ground under a 1x1 light 3 units up casts "
            "a 0.0204-wide contact penumbra; at fov 90 one texel there is 0.054 wide at 128^2 "
            "(the penumbra is 0.38 texel), 0.013 at 512^2, 0.0034 at 2048^2 (6 texels). "
            "Measured there (trace, 8x8 rays, 256x192, normal_offset 0): mean |error| in "
            "shadow 0.094, all too bright, at 128^2; 0.0125 at 2048^2 (0.106 at 128^2 with "
            "the default normal_offset, capped by the contact gap).",
            512, 128, 2048),
        fovParam(),
        Param::real("bias", "Constant bias in world units: a receiver point moves this far "
                            "towards the light before it is tested (every depth-map method).",
                    0.0, 0, 1),
        Param::boolean("adaptive_bias", "Add the adaptive bias of Eq 3.2: one texel's world "
                                        "size at the receiver's depth, divided by n.l.", true),
        Param::real("min_cosine", "Lower clamp of n.l in Eq 3.2, so grazing surfaces get a "
                                  "large but finite bias (\"limited to some small, non-zero "
                                  "value\", §3).", 0.1, 0.001, 1),
        Param::real("normal_offset",
                    "Normal offset (classify and the trace): a receiver point moves this many "
                    "texel widths (at its depth) along its normal before its rays start. Rays "
                    "from a face almost parallel to them (a box's side towards the part of the "
                    "light in front of it) otherwise stay inside the occluder's own near/far "
                    "interval for texels and are blocked (the accuracy suite's box: side "
                    "faces 0.07 too dark, mean |error| in shadow 0.042 at 0, 0.029 at 1, "
                    "0.028 at 1.5, while "
                    "the contact plate goes 0.014 -> 0.018 -> 0.023). Capped by the contact gap: "
                    "the offset may bring the point towards the light by at most a quarter of "
                    "the depth gap to the nearest occluder its rays can meet (classify's "
                    "zNearMin; none within the Eq 3.2 bias: the receiver's own surface), so a "
                    "face it moves sideways (the box's) keeps it all. At 128^2 one texel "
                    "(0.054) is almost the contact plate's 0.06 gap: uncapped, the trace lost "
                    "that shadow (mean |error| in shadow 0.64); capped 0.106 (0.094 with no "
                    "offset).",
                    1.0, 0, 4),
        Param::choiceOrAuto("layers", "Depth layers that model the occluders, for classification and "
                                "the trace: one (near only, §3.2), two (near + far, §3.3) or "
                                "three (+ the eye's depth: a point seen by the eye is free "
                                "space, §3.4, tested over the 3x3 pixels around a point so a "
                                "point within a pixel of an occluder's outline stays solid; "
                                "classification's umbra rule is then off). auto (the default): "
                                "three where one light ray meets more than two occluder "
                                "surfaces, or two occluders with free space between them "
                                "(two plates one above the other), else two.",
                      {"one", "two", "three"}, 1),
        Param::choice(
            "hash",
            "Hash that turns (pixel, ray, frame key) into light samples. md5_16: the thesis's "
            "reduced 16-round MD5, as printed in Appendix A (passes 11 of 15 DIEHARD tests, "
            "§3.1; costs < 10% of the frame, §4.3). md5_64: the full MD5 of Tzeng & Wei 2008, "
            "about 4x the work. pcg3d: Jarzynski & Olano 2020, a few multiplies. Hashes that "
            "teach by failing: md5_4 / md5_8, the listing cut to its first 4 / 8 steps "
            "(\"fewer rounds ... resulted in visible patterns\", §3.1); lcg15, C rand() seeded "
            "with the pixel index (15 bits); lcg32, a 32-bit LCG from the pixel index. "
            "xxhash32: a cheap integer hash in common use (Jarzynski & Olano 2020). The "
            "hash_stats stage measures each one.",
            {kHashKindNames.begin(), kHashKindNames.end()}, int(HashKind::Md5_16)),
        Param::choice(
            "auto_while_playing",
            "What `auto` (resolution, layers, the trace's rays) does while the window's "
            "timeline plays. held (the default): it keeps the choices made at the pose where "
            "playing started (or its last run before), as long as the scene's objects and "
            "the eye size stay the same; the frustum fit (fov_degrees auto) still follows "
            "every pose. Its choices are a policy, not part of any method: a map size that "
            "switches between two frames is a jump in the picture that no method made "
            "(docs/temporal.md), and the analysis is most of this stage's time (an Embree "
            "build and a ray per probe point every pose, docs/decisions/140). every_frame: "
            "decided anew at every pose. Pause, step, scrub, exports, scripts, lessons, the "
            "bench and the CLI always decide at their pose (docs/decisions/141).",
            {"every_frame", "held"}, 1),
    };
  }
  std::string name() const override { return "light"; }
  std::string summary() const override {
    return "The light's frame (Eq 3.1), map size, number of depth layers, the Eq 3.2 bias and "
           "the sample hash: one uniform block shared by every later stage.";
  }
  std::string thesisSection() const override { return "thesis §3, Eq 3.1-3.2"; }

  void run(Frame& frame) override {
    // 1. The light frame of Eq 3.1 (CPU copy for views, reference and the trace panel).
    const Scene& scene = frame.scene;
    // The field of view: `auto` covers every caster's shadow from every point of the light
    // (stages/shared_inputs/light/auto_frustum.h, docs/decisions/135); a fixed one is warned about.
    const Param& fov = param("fov_degrees");
    const FrustumFit fit = fitLightFrustum(scene, fov.max);
    const double fovDegrees = fov.automatic ? fit.fovDegrees : fov.value;
    frame.light = computeLightFrame(scene.light, scene.bounds(), float(fovDegrees));
    const LightFrame& l = frame.light;
    // `auto` (stages/shared_inputs/light/auto_settings.h): the resolution and layers this scene and view
    // need, and the rays per pixel the trace takes when its own `rays` is auto.
    // While the timeline plays (light.auto_while_playing held), the last choice stands when
    // it was made for the same objects, eye size and normal offset (docs/decisions/141).
    const HeldFor heldFor{scene.name, scene.objects.size(), scene.triangleCount(),
                          frame.eyeWidth, frame.eyeHeight, param("normal_offset").asFloat()};
    const bool hold = frame.timelinePlaying && param("auto_while_playing").asInt() == 1 &&
                      decided_ && heldFor == decidedFor_;
    const AutoSettingsWork workBefore = autoSettingsWork();
    if (!hold) {
      chosen_ = chooseAutoSettings(scene, frame.light, frame.eyeWidth, frame.eyeHeight,
                                   param("normal_offset").asFloat());
      decided_ = true, decidedFor_ = heldFor, decidedAt_ = scene.time;
    }
    const AutoSettingsWork workAfter = autoSettingsWork();
    const AutoSettings& chosen = chosen_;
    frame.autoReasons = chosen.reasons;
    if (hold) {
      char held[96];
      std::snprintf(held, sizeof held, "auto: held while playing (decided at t = %.2f s)",
                    decidedAt_);
      frame.autoReasons.insert(frame.autoReasons.begin(), held);
    }
    frame.counters["auto.held"] = hold ? 1 : 0;
    if (fov.automatic) frame.autoReasons.push_back(fit.reason);
    const std::string fovWarning = fov.automatic ? fit.warning : fixedFovWarning(fit, fov.value);
    // The warnings: casters outside any frustum, and a steep occluder no map size shows.
    std::string warning = fovWarning;
    if (!chosen.warning.empty()) warning += (warning.empty() ? "" : "\n") + chosen.warning;
    if (!warning.empty()) {
      if (!fovWarning.empty()) frame.autoReasons.push_back(fovWarning);
      if (!chosen.warning.empty()) frame.autoReasons.push_back(chosen.warning);
      static std::string lastWarning;  // printed once per distinct warning (the log)
      if (warning != lastWarning) std::fprintf(stderr, "%s\n", warning.c_str());
      lastWarning = warning;
    }
    frame.counters["auto.fov_degrees"] = fit.fovDegrees;
    frame.counters["auto.fov_needed"] = fit.neededDegrees;
    frame.counters["auto.fov_uncovered"] = double(fit.uncovered.size());
    frame.light.mapSize = effectiveResolution(param("resolution"), chosen);
    frame.light.layers = param("layers").automatic ? chosen.layers : param("layers").asInt() + 1;
    frame.light.hashKind = param("hash").asInt();
    frame.counters["auto.resolution"] = chosen.resolution;
    // What the resolution weighed: 98% of the penumbra area at 6 texels, the largest map
    // whose build costs no more than the trace, half the area at 6 texels, and the steep
    // occluders' images at 12 texels (docs/decisions/156).
    frame.counters["auto.res_needed"] = chosen.neededResolution;
    frame.counters["auto.res_affordable"] = chosen.affordableResolution;
    frame.counters["auto.res_half_area"] = chosen.halfAreaResolution;
    frame.counters["auto.res_occluder_image"] = chosen.occluderImageResolution;
    frame.counters["auto.layers"] = chosen.layers;
    frame.counters["auto.rays_per_side"] = chosen.raysPerSide;
    frame.counters["auto.probes_in_view"] = chosen.probes;
    // The smallest penumbra in view (its 2nd percentile), in world units, texels and pixels.
    frame.counters["auto.penumbra_world"] = chosen.smallestPenumbraWorld;
    frame.counters["auto.penumbra_texels"] = chosen.smallestPenumbraTexels;
    frame.counters["auto.penumbra_pixels"] = chosen.smallestPenumbraPixels;
    frame.counters["auto.depth_complexity"] = chosen.depthComplexity;
    // What this run's choice cost: the rays its analysis cast (0: the stored answer) and
    // whether it built the Embree scene (a new scene or pose; docs/decisions/140).
    frame.counters["auto.analysis_rays"] = double(workAfter.rays - workBefore.rays);
    frame.counters["auto.bvh_builds"] = double(workAfter.bvhBuilds - workBefore.bvhBuilds);
    const unsigned size = unsigned(frame.light.mapSize);

    // 2. The uniform block (layout: shaders/shared/light_block.h, checked in gpu_layout.h).
    gpu::LightUniforms u{};
    u.lightClipFromWorld = l.lightClipFromWorld;
    u.lightViewFromWorld = l.lightViewFromWorld;
    u.wsLightCenter = glm::vec4(scene.light.center, scene.light.width * scene.light.height);
    u.wsLightRight = glm::vec4(l.right, 0.5f * scene.light.width);
    u.wsLightUp = glm::vec4(l.up, 0.5f * scene.light.height);
    u.wsLightForward = glm::vec4(l.forward, l.lightDepth);
    u.lightDepthRange = glm::vec4(l.zNear, l.zFar, l.tanHalfFovX, l.tanHalfFovY);
    u.mapSize = glm::uvec4(size, size, unsigned(frame.light.layers), 0);
    u.bias = glm::vec4(param("bias").asFloat(), param("adaptive_bias").asBool() ? 1.f : 0.f,
                       param("min_cosine").asFloat(), param("normal_offset").asFloat());
    // The option index is the HashKind, which equals the GLSL HASH_* number (hash_kind.h).
    u.sampling = glm::uvec4(unsigned(frame.light.hashKind), 0, 0, 0);
    frame.outputBuffer(*this, "light").upload(&u, sizeof u);
  }

  const AutoSettings& chosen() const { return chosen_; }

private:
  // What a choice was made for: it is held only for the same of each.
  struct HeldFor {
    std::string scene;
    size_t objects = 0, triangles = 0;
    int eyeWidth = 0, eyeHeight = 0;
    float normalOffset = 0;
    bool operator==(const HeldFor&) const = default;
  };
  AutoSettings chosen_;  // what `auto` chose in the last run
  bool decided_ = false;
  HeldFor decidedFor_;
  double decidedAt_ = 0;  // the scene time of that choice
};

}  // namespace

const AutoSettings& lightAutoSettings(const Frame& frame) {
  static const AutoSettings defaults;
  for (const auto& stage : frame.pipeline.stages())
    if (const auto* light = dynamic_cast<const LightStage*>(stage.get())) return light->chosen();
  return defaults;
}

std::unique_ptr<Stage> makeLightStage() { return std::make_unique<LightStage>(); }
