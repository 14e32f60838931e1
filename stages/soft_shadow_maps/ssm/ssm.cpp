// Stage `ssm`: Soft Shadow Maps (Atty, Holzschuch, Lapierre, Hasenfratz, Hansen, Sillion
// 2006), one or two passes, as the paper's Fig. 3 in numbered steps:
//   1. receiver map: depth of the receivers (receiver_only objects) from the light;
//   2. occluder map(s): nearest surfaces of the occluders (and, two passes, the farthest);
//   3. each occluder texel is a micro-patch parallel to the light (§3.2);
//   4. one instanced quad per micro-patch covers its penumbra extent in the soft shadow map
//      (§3.3; no read-back to the CPU);
//   5. per soft-shadow-map texel, the fraction of the light the micro-patch hides from the
//      receiver there, summed by additive blending (§3.4), in R32F or R16F (§4.1.3, Fig. 14);
//   6. the soft shadow map projected onto the scene: visibility = 1 - occlusion, clamped.
// The maps share the light's frustum (Eq 3.1 of the thesis): aligned with the rectangular
// light and of its aspect ratio, seen from the projection point behind the light centre.
#include <algorithm>
#include <cstring>
#include <cmath>
#include <cstdio>

#include "core/frame.h"
#include "core/run_control.h"
#include "gl/gpu_layout_ssm.h"
#include "gl/shader_program.h"
#include "shared/screen_pass_layout.h"
#include "shared_inputs/light/auto_settings.h"
#include "shared_inputs/light/light_input.h"
#include "soft_shadow_maps/ssm/auto_ssm.h"
#include "soft_shadow_maps/ssm/ssm_cost.h"

// Each pass's bindings (shaders/shared/ssm_layout.h), within GL 4.5's minimums.
static_assert(gpu::distinctBelow({FRAME_BLOCK_BINDING, LIGHT_BLOCK_BINDING, SSM_PARAMS_BINDING},
                                 gpu::kUniformBindings));
static_assert(gpu::distinctBelow({DEPTH_BOUNDS_BINDING, SSM_COUNTERS_BINDING, SSM_WORK_BINDING},
                                 gpu::kStorageBindings));
static_assert(gpu::distinctBelow({SSM_PATCHES_OCCLUDER_UNIT, SSM_PATCHES_RECEIVER_UNIT},
                                 gpu::kTextureUnits));
static_assert(gpu::distinctBelow({SSM_PICKED_OCCLUDER_UNIT, SSM_PICKED_RECEIVER_UNIT,
                                  SSM_PICKED_WS_POSITION_UNIT}, gpu::kTextureUnits));
static_assert(gpu::distinctBelow({SSM_PROJECT_WS_POSITION_UNIT, SSM_PROJECT_RECEIVER_UNIT,
                                  SSM_PROJECT_SOFT_SHADOW_MAP_UNIT}, gpu::kTextureUnits));
static_assert(gpu::distinctBelow({SSM_PROJECT_VISIBILITY_IMAGE}, gpu::kImageUnits));
static_assert(gpu::distinctBelow({DEPTH_BOUNDS_MAP_UNIT}, gpu::kTextureUnits) &&
              gpu::distinctBelow({DEPTH_BOUNDS_EMPTY_LOCATION}, gpu::kUniformLocations));

namespace {

constexpr int kPickedLightSize = 256;  // texels of the picked-receiver view of the light
constexpr double kFragmentsPerTile = 5e7;  // a cancel check per this many estimated fragments

class SoftShadowMapStage final : public Stage {
public:
  SoftShadowMapStage() {
    inputs_ = {
        Input::texture("wsPosition", "Eye points the soft shadow map is projected onto "
                                     "(G-buffer).", GL_RGBA32F),
        lightInput(),
    };
    outputs_ = {
        {"visibility", "1 - accumulated occlusion, clamped to [0,1]; occluders are lit (no "
                       "self-shadowing).", GL_R32F, {"visibility"}, {0, 0, 1, Colormap::Gray},
         kRoleShadowMethod},
        {"receiverMap", "Step 1: linear light depth of the receivers; 1 where none.",
         GL_DEPTH_COMPONENT32F, {"lsDepthReceiver"}, {0, 0, 1, Colormap::Gray}},
        {"occluderMap", "Step 2: linear light depth of the nearest occluder; each texel is a "
                        "micro-patch.", GL_DEPTH_COMPONENT32F, {"lsDepthOccluder"},
         {0, 0, 1, Colormap::Gray}},
        {"occluderBackMap", "Step 2, two passes: the farthest occluder surfaces (§3.5); 0 "
                            "where none.", GL_DEPTH_COMPONENT32F, {"lsDepthOccluderBack"},
         {0, 0, 1, Colormap::Gray}},
        {"softShadowMap", "Step 5: occlusion summed over micro-patches, in light space (r: "
                          "front pass, g: back pass); above 1 where patches overlap.",
         GL_RG32F, {"occlusionFront", "occlusionBack"}, {0, 0, 1, Colormap::Perceptual}},
        {"patchCount", "Micro-patches that hid some of the light from each texel's receiver.",
         GL_R32F, {"patches"}, {0, 0, 1000, Colormap::Perceptual, true}},
        {"pickedLight", "The light rectangle seen from the picked receiver: how many "
                        "back-projected micro-patches cover each point (0: gap, a light leak; "
                        "2+: overlap). r: front pass, g: back pass.",
         GL_RG32F, {"coverFront", "coverBack"}, {0, 0, 3, Colormap::Perceptual}},
        {"pickedFootprint", "The picked occluder texel's quad on the soft shadow map: r = its "
                            "occlusion, g = 1 inside the quad.",
         GL_RG32F, {"occlusion", "insideQuad"}, {0, 0, 0.05f, Colormap::Perceptual}},
    };
    params_ = {
        Param::choice("passes", "one: the nearest occluder surfaces only (§3.1). two: also the "
                      "farthest surfaces, each pass its own soft shadow map, merged by their "
                      "maximum (§3.5, Fig. 10-11).", {"one", "two"}, 0),
        Param::choice("accumulation", "Format the micro-patches are summed in: r32f, or r16f "
                      "(10-bit mantissa), which loses small contributions added to large sums "
                      "(§4.1.3, Appendix A, Fig. 14: worse at high resolution).",
                      {"r32f", "r16f"}, 0),
        Param::integerOrAuto(
            "resolution",
            "Texels per side of the occluder, receiver and soft shadow maps. Cost grows with "
            "its 4th power (patches x texels per patch); the paper finds ~200 enough (§4.2.3) "
            "and uses 128 in Fig. 18-20, but a contact penumbra narrower than a texel becomes "
            "a step (a plate 0.06 above the ground: mean |error| in shadow 0.106-0.254 at 128, "
            "0.057 at 512). auto (the default): so that 98% of the penumbra area in view spans "
            "4 texels, in multiples of 128 in [128, 1024], the largest whose estimated "
            "micro-patch fragments stay within 2e7 and ssm.budget (64, 32 or 16 where even "
            "128 would not) "
            "(stages/soft_shadow_maps/ssm/auto_ssm.h).",
            128, 16, 1024),
        Param::real("fill", "Fraction of the occluder map whose micro-patches are drawn, row by "
                    "row from the bottom: slide it to watch the soft shadow map fill up (1: all).",
                    1.0, 0.0, 1.0),
        Param::real("receiver_tolerance", "How far in front of the receiver map an eye point "
                    "still counts as that receiver, in receiver-depth steps between neighbouring "
                    "texels (its slope). Points farther in front are occluders: SSM computes no "
                    "self-shadowing, they stay lit.", 2.0, 0.0, 64.0),
        Param::real("budget", "Millions of fragments the micro-patch quads may cover in a run, "
                    "estimated from the scene before they are drawn (ssm_cost.h: patches x "
                    "texels per quad, which grows without bound as an occluder nears the light); "
                    "a run over it is refused. 0: no limit.", 2000.0, 0.0, 1e9),
        Param::integer("pick_x", "Eye pixel (column) of the receiver whose back-projected "
                       "micro-patches the pickedLight view draws; -1: none.", -1, -1, 8192),
        Param::integer("pick_y", "Eye pixel (row from the top) of the picked receiver.", -1, -1,
                       8192),
        Param::integer("patch_x", "Occluder-map texel (column) whose quad the pickedFootprint "
                       "view draws; -1: none.", -1, -1, 1023),
        Param::integer("patch_y", "Occluder-map texel (row, 0 at the bottom) of that quad.", -1,
                       -1, 1023),
    };
    // pickedLight from pick_x/y; pickedFootprint from patch_x/y on the resolution-sized maps.
    capabilities_ = kCapabilityPicksEyePixel | kCapabilityPicksMapTexel;
  }
  ~SoftShadowMapStage() override {
    if (vertexArray_) glDeleteVertexArrays(1, &vertexArray_);
  }
  std::string name() const override { return "ssm"; }
  std::string summary() const override {
    return "Soft shadow maps (Atty et al. 2006): every occluder texel is a micro-patch whose "
           "hidden fraction of the light is summed into a light-space map (one or two passes, "
           "R32F or R16F). Receivers (the scene's receiver_only objects) and occluders are "
           "separate: no self-shadowing.";
  }
  std::string thesisSection() const override { return "Atty et al. 2006 §3"; }

  void run(Frame& frame) override {
    bindLightInput(frame, *this);
    const bool twoPasses = param("passes").asEnum() == "two";
    // The cost model (ssm_cost.h): the scene rasterized coarsely from the light, on the CPU,
    // evaluated at any resolution: for `auto` and for the budget below.
    const SsmCostModel costModel(frame.scene, frame.light);
    int n = param("resolution").asInt();
    if (param("resolution").automatic) {  // auto_ssm.h: the need from the auto policy, capped by cost
      const SsmResolutionChoice choice = chooseSsmResolution(
          lightAutoSettings(frame).ssmNeed, costModel, twoPasses ? 2 : 1, param("budget").asFloat());
      n = choice.resolution;
      frame.autoReasons.push_back(choice.reason);
      frame.counters["auto.ssm_resolution"] = n;
      frame.counters["auto.ssm_needed"] = lightAutoSettings(frame).ssmNeed.exact;
    }
    // Steps 1-2: receiver and occluder maps, linear light depth (light_block.h).
    GlTexture& receiverMap = frame.output(*this, "receiverMap", n, n);
    GlTexture& occluderMap = frame.output(*this, "occluderMap", n, n);
    GlTexture& occluderBack = frame.output(*this, "occluderBackMap", n, n);
    renderDepth(frame, receiverMap, GL_LESS, 1.0f, /*receivers=*/true);
    renderDepth(frame, occluderMap, GL_LESS, 1.0f, false);
    renderDepth(frame, occluderBack, GL_GREATER, 0.0f, false);
    // The bounds stay on the GPU (the patch pass sizes its quads with the receivers'); the
    // occluder texels (micro-patches) are counted after the frame.
    depthBounds(occluderMap, 1.0f, occluderBounds_);
    depthBounds(receiverMap, 1.0f, receiverBounds_);
    frame.readAfterFrame(occluderBounds_, 0, sizeof(gpu::DepthBounds),
                         [](const std::vector<unsigned char>& bytes, Frame& frame) {
                           gpu::DepthBounds read{};
                           std::memcpy(&read, bytes.data(), sizeof read);
                           frame.counters["ssm.patches"] = read.count;
                         });

    gpu::SsmParams params{};
    const int h = frame.eyeHeight, pickY = param("pick_y").asInt();
    params.map = {n, 0, twoPasses ? 2 : 1, 0};
    params.pick = {param("pick_x").asInt(), pickY < 0 ? -1 : h - 1 - pickY,
                   param("patch_x").asInt(), param("patch_y").asInt()};
    params.tolerance = {param("receiver_tolerance").asFloat(), 0, 0, 0};

    // Before steps 3-5, their cost from the scene: refused over the budget (core/run_control.h).
    const SsmCostEstimate cost = costModel.at(n, twoPasses ? 2 : 1, param("fill").asFloat());
    frame.counters["ssm.estimatedFragments"] = cost.fragments;
    frame.counters["ssm.estimatedPatches"] = cost.patches;
    checkBudget(cost, n);
    throwIfRunCancelled("in ssm, before the micro-patches");

    // Steps 3-5: the soft shadow map(s) and the patch count.
    const GLenum format = param("accumulation").asEnum() == "r16f" ? GL_RG16F : GL_RG32F;
    if (accumulation_.id() == 0 || accumulation_.width() != n || accumulation_.internalFormat() != format)
      accumulation_ = GlTexture(format, n, n);
    GlTexture& patchCount = frame.output(*this, "patchCount", n, n);
    const int drawn = int(std::lround(param("fill").asFloat() * n * n));
    beginAdditive(accumulation_, &patchCount);
    // The measured work (SsmWork: every quad's fragments), against the estimate above.
    const gpu::SsmWork noWork{};
    workBuffer_.upload(&noWork, sizeof noWork);
    frame.readAfterFrame(workBuffer_, 0, sizeof noWork,
                         [](const std::vector<unsigned char>& bytes, Frame& frame) {
                           gpu::SsmWork read{};
                           std::memcpy(&read, bytes.data(), sizeof read);
                           frame.counters["ssm.quadFragments"] =
                               double(read.high) * 4294967296.0 + double(read.low);
                         });
    // A run estimated to be long is drawn in tiles of the soft shadow map (a scissor each:
    // every fragment still drawn once, the sums unchanged), about kFragmentsPerTile each, with
    // a cancel check after each tile, so Esc or --time-limit stops it within seconds.
    const int tiles = std::clamp(int(std::ceil(std::sqrt(cost.fragments / kFragmentsPerTile))), 1, 64);
    drawPatchesInTiles(params, occluderMap, receiverMap, 0, drawn, tiles, n);
    if (twoPasses) drawPatchesInTiles(params, occluderBack, receiverMap, 1, drawn, tiles, n);
    endAdditive();
    GlTexture& softShadowMap = frame.output(*this, "softShadowMap", n, n);
    copyColor(accumulation_, softShadowMap);

    // Step 6: projection onto the scene.
    GlTexture& visibility = frame.output(*this, "visibility", frame.eyeWidth, frame.eyeHeight);
    gpu::SsmCounters counters{};
    counterBuffer_.upload(&counters, sizeof counters);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SSM_COUNTERS_BINDING, counterBuffer_.id());
    bindParams(params);
    projectProgram_.use();
    glBindTextureUnit(SSM_PROJECT_WS_POSITION_UNIT, frame.input(*this, "wsPosition").id());
    glBindTextureUnit(SSM_PROJECT_RECEIVER_UNIT, receiverMap.id());
    glBindTextureUnit(SSM_PROJECT_SOFT_SHADOW_MAP_UNIT, softShadowMap.id());
    glBindImageTexture(SSM_PROJECT_VISIBILITY_IMAGE, visibility.id(), 0, GL_FALSE, 0,
                       GL_WRITE_ONLY, GL_R32F);
    dispatchRows(frame.eyeWidth, frame.eyeHeight, kImageResults | kBufferResults);
    frame.readAfterFrame(counterBuffer_, 0, sizeof counters,
                         [](const std::vector<unsigned char>& bytes, Frame& frame) {
                           gpu::SsmCounters read{};
                           std::memcpy(&read, bytes.data(), sizeof read);
                           frame.counters["ssm.clampedPixels"] = read.clampedPixels;
                           frame.counters["ssm.occluderPixels"] = read.occluderPixels;
                         });

    // The picked views.
    GlTexture& pickedLight = frame.output(*this, "pickedLight", kPickedLightSize, kPickedLightSize);
    beginAdditive(pickedLight, nullptr);
    const bool pickedReceiver = params.pick.x >= 0 && params.pick.x < frame.eyeWidth &&
                                params.pick.y >= 0 && params.pick.y < h;
    if (pickedReceiver)
      for (int pass = 0; pass < (twoPasses ? 2 : 1); ++pass) {
        params.map.y = pass;
        bindParams(params);
        glColorMaski(0, pass == 0, pass == 1, GL_FALSE, GL_FALSE);
        pickedLightProgram_.use();
        glBindTextureUnit(SSM_PICKED_OCCLUDER_UNIT, (pass == 0 ? occluderMap : occluderBack).id());
        glBindTextureUnit(SSM_PICKED_RECEIVER_UNIT, receiverMap.id());
        glBindTextureUnit(SSM_PICKED_WS_POSITION_UNIT, frame.input(*this, "wsPosition").id());
        glBindVertexArray(emptyVertexArray());
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, n * n);
      }
    endAdditive();
    GlTexture& footprint = frame.output(*this, "pickedFootprint", n, n);
    beginAdditive(footprint, nullptr);
    if (params.pick.z >= 0 && params.pick.z < n && params.pick.w >= 0 && params.pick.w < n) {
      params.map.y = 0;
      params.map.w = 1;
      drawPatches(params, occluderMap, receiverMap, 0, 1);
    }
    endAdditive();
  }

private:
  void checkBudget(const SsmCostEstimate& cost, int n) {
    const double budget = param("budget").asFloat();
    if (budget <= 0 || cost.fragments <= budget * 1e6) return;
    char message[768];
    std::snprintf(message, sizeof message,
                  "ssm: this run would blend about %.3g fragments (%.3g micro-patches x %.3g "
                  "texels per quad at ssm.resolution=%d: an occluder close to the light gives "
                  "each patch a quad the size of the map), over ssm.budget=%g million. Lower "
                  "ssm.resolution (auto, the default, picks one within budget) or move the light "
                  "away from the occluders, or run it anyway "
                  "with --set ssm.budget=%.0f (0: no limit)",
                  cost.fragments, cost.patches, cost.meanQuadTexels, n, budget,
                  std::ceil(cost.fragments * 1.25e-6));
    throw RunBudgetExceeded(message, "ssm.budget", cost.fragments * 1e-6, budget);
  }

  void renderDepth(Frame& frame, GlTexture& target, GLenum depthTest, float clearDepth,
                   bool receivers) {
    glNamedFramebufferTexture(depthFramebuffer_.id(), GL_DEPTH_ATTACHMENT, target.id(), 0);
    glNamedFramebufferDrawBuffer(depthFramebuffer_.id(), GL_NONE);
    depthFramebuffer_.checkComplete("ssm");
    glBindFramebuffer(GL_FRAMEBUFFER, depthFramebuffer_.id());
    glViewport(0, 0, target.width(), target.height());
    glClearNamedFramebufferfi(depthFramebuffer_.id(), GL_DEPTH_STENCIL, 0, clearDepth, 0);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(depthTest);
    glDisable(GL_CULL_FACE);  // as light_layers: sheets and open meshes stay occluders
    depthProgram_.use();
    if (receivers) frame.gpuScene.drawReceivers();
    else frame.gpuScene.draw(/*includeReceivers=*/false);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }

  void depthBounds(const GlTexture& map, float empty, GlBuffer& buffer) {
    const gpu::DepthBounds bounds{0x7f7fffffu, 0u, 0u, 0u};
    buffer.upload(&bounds, sizeof bounds);
    boundsProgram_.use();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, DEPTH_BOUNDS_BINDING, buffer.id());
    glBindTextureUnit(DEPTH_BOUNDS_MAP_UNIT, map.id());
    glUniform1f(DEPTH_BOUNDS_EMPTY_LOCATION, empty);
    glDispatchCompute(GLuint((map.width() + 7) / 8), GLuint((map.height() + 7) / 8), 1);
    glMemoryBarrier(kBufferResults);
  }

  // Colour attachment 0 (and 1) cleared to 0, summed into with additive blending.
  void beginAdditive(const GlTexture& target, const GlTexture* second) {
    glNamedFramebufferTexture(colorFramebuffer_.id(), GL_COLOR_ATTACHMENT0, target.id(), 0);
    glNamedFramebufferTexture(colorFramebuffer_.id(), GL_COLOR_ATTACHMENT1,
                              second ? second->id() : 0, 0);
    const GLenum both[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(colorFramebuffer_.id(), second ? 2 : 1, both);
    colorFramebuffer_.checkComplete("ssm");
    glBindFramebuffer(GL_FRAMEBUFFER, colorFramebuffer_.id());
    glViewport(0, 0, target.width(), target.height());
    const float zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(colorFramebuffer_.id(), GL_COLOR, 0, zero);
    if (second) glClearNamedFramebufferfv(colorFramebuffer_.id(), GL_COLOR, 1, zero);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
  }
  void endAdditive() {
    glDisable(GL_BLEND);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }

  // count: add this draw's quad fragments to SsmWork (once per pass, not per tile).
  void drawPatches(gpu::SsmParams params, const GlTexture& occluders, const GlTexture& receivers,
                   int pass, int instances, bool count = false) {
    params.map.y = pass;
    params.tolerance.y = count ? 1.0f : 0.0f;
    bindParams(params);
    // This pass's channel of the soft shadow map; the patch count sums both passes.
    const bool footprint = params.map.w != 0;
    glColorMaski(0, pass == 0 || footprint, pass == 1 || footprint, GL_FALSE, GL_FALSE);
    patchProgram_.use();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, DEPTH_BOUNDS_BINDING, receiverBounds_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SSM_WORK_BINDING, workBuffer_.id());
    glBindTextureUnit(SSM_PATCHES_OCCLUDER_UNIT, occluders.id());
    glBindTextureUnit(SSM_PATCHES_RECEIVER_UNIT, receivers.id());
    glBindVertexArray(emptyVertexArray());
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, instances);
    glBindVertexArray(0);
    if (count) glMemoryBarrier(kBufferResults);
  }

  void drawPatchesInTiles(const gpu::SsmParams& params, const GlTexture& occluders,
                          const GlTexture& receivers, int pass, int instances, int tiles, int n) {
    if (tiles <= 1) return drawPatches(params, occluders, receivers, pass, instances, true);
    for (int ty = 0; ty < tiles; ++ty)
      for (int tx = 0; tx < tiles; ++tx) {
        const int x0 = tx * n / tiles, x1 = (tx + 1) * n / tiles;
        const int y0 = ty * n / tiles, y1 = (ty + 1) * n / tiles;
        glEnable(GL_SCISSOR_TEST);
        glScissor(x0, y0, x1 - x0, y1 - y0);
        drawPatches(params, occluders, receivers, pass, instances, tx == 0 && ty == 0);
        glDisable(GL_SCISSOR_TEST);
        glFinish();  // the tile is done before the check
        setRunProgress("in ssm, tile " + std::to_string(ty * tiles + tx + 1) + " of " +
                       std::to_string(tiles * tiles) + " of pass " + std::to_string(pass + 1));
        pollRunCancel();
        if (runCancelRequested()) {
          endAdditive();  // GL state as every stage leaves it
          throwIfRunCancelled("in ssm after " + std::to_string(ty * tiles + tx + 1) + " of " +
                              std::to_string(tiles * tiles) + " tiles of pass " +
                              std::to_string(pass + 1));
        }
      }
  }

  void bindParams(const gpu::SsmParams& params) {
    paramBuffer_.upload(&params, sizeof params);
    glBindBufferBase(GL_UNIFORM_BUFFER, SSM_PARAMS_BINDING, paramBuffer_.id());
  }

  void copyColor(const GlTexture& from, const GlTexture& to) {
    glNamedFramebufferTexture(readFramebuffer_.id(), GL_COLOR_ATTACHMENT0, from.id(), 0);
    glNamedFramebufferTexture(colorFramebuffer_.id(), GL_COLOR_ATTACHMENT0, to.id(), 0);
    glNamedFramebufferTexture(colorFramebuffer_.id(), GL_COLOR_ATTACHMENT1, 0, 0);
    glNamedFramebufferDrawBuffer(colorFramebuffer_.id(), GL_COLOR_ATTACHMENT0);
    glBlitNamedFramebuffer(readFramebuffer_.id(), colorFramebuffer_.id(), 0, 0, from.width(),
                           from.height(), 0, 0, to.width(), to.height(), GL_COLOR_BUFFER_BIT,
                           GL_NEAREST);
  }

  GLuint emptyVertexArray() {
    if (!vertexArray_) glCreateVertexArrays(1, &vertexArray_);
    return vertexArray_;
  }

  ShaderProgram depthProgram_{{{GL_VERTEX_SHADER, "shared/scene.vert"},
                               {GL_FRAGMENT_SHADER, "shared_inputs/light_layers/light_layers.frag"}},
                              "#define LIGHT_PASS\n"};
  ShaderProgram boundsProgram_{{{GL_COMPUTE_SHADER, "shared/depth_bounds.comp"}}};
  ShaderProgram patchProgram_{{{GL_VERTEX_SHADER, "soft_shadow_maps/ssm/ssm_patches.vert"},
                               {GL_FRAGMENT_SHADER, "soft_shadow_maps/ssm/ssm_patches.frag"}}};
  ShaderProgram pickedLightProgram_{{{GL_VERTEX_SHADER, "soft_shadow_maps/ssm/ssm_picked_light.vert"},
                                     {GL_FRAGMENT_SHADER, "soft_shadow_maps/ssm/ssm_count.frag"}}};
  ShaderProgram projectProgram_{{{GL_COMPUTE_SHADER, "soft_shadow_maps/ssm/ssm_project.comp"}}};
  GlFramebuffer depthFramebuffer_, colorFramebuffer_, readFramebuffer_;
  GlTexture accumulation_;
  GlBuffer occluderBounds_, receiverBounds_, counterBuffer_, paramBuffer_, workBuffer_;
  GLuint vertexArray_ = 0;  // for attribute-less draws
};

}  // namespace

std::unique_ptr<Stage> makeSoftShadowMapStage() { return std::make_unique<SoftShadowMapStage>(); }
