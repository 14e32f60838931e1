// Stage `trace` (thesis §3-3.7, Algorithms 1 and 2): n x n rays per receiver through the
// light's depth layers, in the deferred form (a compute pass over the G-buffer) or the
// forward form (every rasterized fragment traces; thesis Table 4.1).
#include <cstring>
#include <cmath>
#include <cstdio>

#include "monte_carlo/trace/trace_steps.h"
#include "shared_inputs/light/auto_params.h"
#include "core/frame.h"
#include "gl/renderer_calibration.h"
#include "shared_inputs/light/light_input.h"
#include "gl/gpu_layout_trace.h"

namespace gpu {
#include "monte_carlo/classify/classify_layout.h"
#include "shared/screen_pass_layout.h"
}  // namespace gpu
#include "shared_inputs/minmax/minmax_build.h"
#include "gl/nbuffer_build.h"
#include "gl/hash_kind.h"
#include "gl/shader_program.h"

// The option index of trace.search and trace.sampling is the GLSL enum (trace_layout.h), and
// light.layers' index + 1 the layer count: the option lists below are in this order.
static_assert(SEARCH_LINEAR == 0 && SEARCH_LINEAR_BINARY == 1 && SEARCH_HIERARCHICAL == 2);
static_assert(SAMPLING_JITTERED == 0 && SAMPLING_RANDOM == 1);
// trace.rays' upper bound (auto's too: stages/shared_inputs/light/auto_settings.cpp stops at 8): a pixel's
// counts of rays, searched rays and early outs fit the record's fields (trace_layout.h).
constexpr int kMaxRaysPerSide = 8;
static_assert(kMaxRaysPerSide * kMaxRaysPerSide < (1 << TRACE_COUNT_BITS));

namespace {

// The hierarchy Algorithm 2 and the region early out (§3.7) search: a choice among the
// stages whose output has the hierarchy role (nbuffer, minmax), by trace.hierarchy.
Input hierarchyInput() {
  Input input = Input::choice("levels", "Hierarchy of occluder depth bounds (Algorithm 2, "
                              "early out of §3.7): N-buffer or min-max mipmap.",
                              kRoleHierarchy, "hierarchy", "nbuffer", /*allowNone=*/false);
  input.format = GL_RGBA32F;
  input.decidedAfter = "light";  // `auto` reads the map size the light stage settled
  return input;
}

// `auto` hierarchy: the min-max mipmap once the N-buffer's build costs more than the
// min-max mipmap's looser bounds cost over the eye (classification's conservative cells
// call more pixels penumbra, and rays are shortened less: classify 1.4-2.1x, the trace
// 1.0-1.7x in the runs below). The N-buffer's build is R^2 x (its level count,
// ceil(log2 R) + 1) texel-levels; the extra cost of the looser bounds grows with the eye's
// pixels. The constant sits between the measured crossovers (even at 10.7 texel-levels per
// eye pixel and below, min-max faster from 19 up) and keeps the window's default view of
// spheres (11.0) on the N-buffer, where the min-max mipmap measured 1.36-1.56x slower:
// docs/decisions/027-auto-hierarchy-rule.md has the runs and the command.
// The fallback: `auto` uses the crossover measured on its renderer (gl/renderer_calibration.h).
constexpr double kNBufferTexelLevelsPerEyePixel = kFallbackNBufferTexelLevelsPerEyePixel;

class TraceStage final : public Stage {
public:
  TraceStage() {
    inputs_ = {
        Input::texture("wsPosition", "Receivers (G-buffer).", GL_RGBA32F),
        Input::texture("wsNormal", "Receiver normals (Eq 3.2 bias, back-face early out).",
                       GL_RGBA32F),
        Input::texture("near", "Near layer (§3.2).", GL_DEPTH_COMPONENT32F),
        Input::texture("far", "Far layer (§3.3).", GL_R32F),
        hierarchyInput(),
        Input::texture("mask", "Classes of §3.6 (lit and umbra pixels are not traced).", GL_R32F),
        Input::texture("zRange", "Occluder depth bounds per pixel (ray shortening, §3.7).",
                       GL_RGBA32F),
        Input::buffer("tracedPixels", "The pixels classification left to trace, with their "
                                      "count (classify_layout.h)."),
        lightInput(),
    };
    outputs_ = {
        {"visibility", "Unfiltered visibility: the fraction of this pixel's rays that reach the "
                       "light.", GL_R32F, {"visibility"}, {0, 0, 1, Colormap::Gray},
         kRoleShadowMethod},
        {"cost", "Per pixel: texel fetches, search iterations, rays searched, rays ended by an "
                 "early out.", GL_RGBA32F, {"fetches", "iterations", "raysSearched", "earlyOuts"},
         {0, 0, 200, Colormap::Perceptual, true}},
    };
    params_ = {
        Param::integerOrAuto("rays", "Rays per pixel along each side of the light: n x n rays "
                                     "(§3.1). auto: more where the smallest penumbra in view is "
                                     "too narrow for the filter to average (auto.* counters).",
                             2, 1, kMaxRaysPerSide),
        Param::choice("sampling", "jittered: one random sample in each cell of an n x n grid on "
                                  "the light; random: anywhere on the light (§3.1, Fig 3.3).",
                      {"jittered", "random"}, 0),
        Param::choice("search", "How a ray is traced: linear (fixed step), linear_binary "
                                "(binary refinement on suspicious transitions, §3.3) or "
                                "hierarchical (Algorithm 2 over trace.hierarchy, §3.5).",
                      {"linear", "linear_binary", "hierarchical"}, 2),
        Param::choiceOrAuto(
            "hierarchy",
            "What classification, the hierarchical search and the region early out read: "
            "nbuffer (windows of 2^n around every texel, §3.5: exact bounds over any "
            "rectangle, log2 R + 1 full-size levels to build) or minmax (a min-max mipmap, "
            "quadtree-aligned cells, a third of one level's memory, about 1/19 of the "
            "N-buffer's build at 2048^2; conservative bounds, so more pixels are traced). "
            "auto (the default): minmax once the N-buffer's texel-levels "
            "(R^2 x levels) exceed 12 per eye pixel: of auto's map sizes, from 640 at "
            "640x480, from 768 at the window's 616x665 (measured crossovers between 10.7 "
            "and 14.7).",
            {}, 0),  // options: the stages with the hierarchy role (Pipeline fills them)
        Param::real("linear_step", "Step of the linear search, in shadow-map texels.", 1.0,
                    0.25, 16),
        Param::integer("binary_steps", "Bisections per suspicious transition (linear_binary).",
                       6, 0, 16),
        Param::boolean("early_out_backface", "A light sample behind the surface (n.l <= 0) "
                                             "blocks the ray without tracing (§3.7).", true),
        Param::boolean("early_out_inside", "An end point inside a solid blocks the ray after one "
                                           "fetch (§3.7).", true),
        Param::boolean("early_out_region", "One N-buffer fetch (min-max mipmap: up to 2 x 2) "
                                           "over the ray's projection; if it holds no occluder "
                                           "at the ray's depths, the ray is free (§3.7).", true),
        Param::boolean("shorten_rays", "Clip each ray to the depths [zNearMin, zFarMax] that "
                                       "classification found for its pixel (§3.7, Fig 3.9).",
                       true),
        Param::boolean("use_classification", "Skip pixels classified lit or umbra (§3.6).",
                       true),
        Param::boolean("deferred", "Trace per G-buffer pixel (deferred, Algorithm 1) or per "
                                   "rasterized fragment (forward; Table 4.1).", true),
        Param::real("eye_tolerance", "Three layers: a point counts as free space (seen by the "
                                     "eye) only if it lies at least this far (world units) in "
                                     "front of the visible surface's tangent plane at each "
                                     "covered pixel of the 3x3 block around it. Must be below "
                                     "the rays' bias for their own end points to count as "
                                     "free (the Fig 3.5 lesson: 0.002 there).", 0.02, 0, 1),
        Param::integer("max_iterations", "Cap on search iterations per ray (a safety net; "
                                         "reaching it is counted and reported).", 512, 16, 4096),
        Param::integer("record_x", "Pixel (x, image column) whose every step is recorded for "
                                   "the inspector and `penumbra trace`; -1: none.", -1, -1, 8192),
        Param::integer("record_y", "Pixel (y, row from the top) whose steps are recorded.", -1,
                       -1, 8192),
    };
    capabilities_ = kCapabilityRecordsRays;  // the trace panel: record_x/y, rays, near, far
  }
  std::string name() const override { return "trace"; }
  std::string summary() const override {
    return "Monte Carlo rays from each pixel to random points on the light, through the depth "
           "layers: the unfiltered visibility, and per pixel the texel fetches, search "
           "iterations, rays searched and early outs.";
  }
  std::string thesisSection() const override { return "thesis §3.1-3.7, Alg. 2"; }

  AutoChoice chooseAuto(const std::string& key, const Frame& frame) const override {
    if (key != "hierarchy") return Stage::chooseAuto(key, frame);
    const double size = frame.light.mapSize;
    const double texelLevels = size * size * nbufferLevelCount(int(size), int(size));
    const double eyePixels = double(frame.eyeWidth) * frame.eyeHeight;
    const RendererCalibration calibration = activeRendererCalibration();
    const double crossover = calibration.nbufferTexelLevelsPerEyePixel;
    const bool minmax = texelLevels > crossover * eyePixels;
    char reason[320];
    std::snprintf(reason, sizeof reason,
                  "hierarchy %s: the N-buffer of a %d^2 map is %.3g M texel-levels, %.1f per "
                  "eye pixel (%dx%d), %s the %.3g above which the min-max mipmap is faster (%s)",
                  minmax ? "minmax" : "nbuffer", int(size), texelLevels / 1e6,
                  texelLevels / eyePixels, frame.eyeWidth, frame.eyeHeight,
                  minmax ? "above" : "not above", crossover,
                  calibration.source == "fallback" ? "the constant" : "calibrated");
    return {minmax ? "minmax" : "nbuffer", reason};
  }

  void run(Frame& frame) override {
    const int w = frame.eyeWidth, h = frame.eyeHeight;
    GlTexture& visibility = frame.output(*this, "visibility", w, h);
    // Demand (docs/decisions/014-outputs-nobody-asked-for.md): the deferred pass writes the
    // per-pixel cost only when someone shows or exports it (an RGBA32F store per traced pixel and a
    // clear of the image: trace 0.83 without them); the totals below are counted either way. The
    // forward pass writes it as a second colour output, nearly free.
    const bool deferred = param("deferred").asBool();
    const bool costWanted = !deferred || frame.wanted(name() + ".cost");
    if (!costWanted) frame.textures.erase(name() + ".cost");
    GlTexture* cost = costWanted ? &frame.output(*this, "cost", w, h) : nullptr;
    const GlTexture& levels = frame.input(*this, "levels");
    const GlTexture& nearLayer = frame.input(*this, "near");

    // 1. Parameters -> the std140 block (shaders/shared/trace_layout.h).
    gpu::TraceParams params{};
    const int recordY = param("record_y").asInt();
    bindLightInput(frame, *this);
    // `auto` rays: what the scene and view need (stage `light`, stages/shared_inputs/light/auto_settings.h).
    const int rays = effectiveRays(param("rays"), lightAutoSettings(frame));
    params.config = {rays, param("sampling").asInt(), param("search").asInt(), frame.light.layers};
    params.switches = {param("early_out_backface").asBool(), param("early_out_inside").asBool(),
                       param("early_out_region").asBool(), param("shorten_rays").asBool()};
    const bool minmax = !levels.isArray();  // the min-max mipmap is 2D, the N-buffer an array
    params.limits = {param("max_iterations").asInt(), param("binary_steps").asInt(),
                     minmax ? HIERARCHY_MINMAX : HIERARCHY_NBUFFER,
                     param("use_classification").asBool()};
    params.stepping = {param("linear_step").asFloat(), 0, 0, 0};
    params.record = {param("record_x").asInt(), recordY < 0 ? -1 : h - 1 - recordY,
                     kRecordCapacity,
                     minmax ? minmaxTopLevel(nearLayer.width(), nearLayer.height()) : levels.layers() - 1};
    params.eye = {param("eye_tolerance").asFloat(), 0, 0, 0};
    paramsBuffer_.upload(&params, sizeof params);
    glBindBufferBase(GL_UNIFORM_BUFFER, binding::kTraceParams, paramsBuffer_.id());

    // 2. Cleared record and total buffers.
    //    Allocated once; each frame only the record count and the totals are zeroed (the
    //    records past the count are never read).
    if (!buffersAllocated_) {
      recordsBuffer_.upload(nullptr, 16 + kRecordCapacity * sizeof(gpu::TraceStep));
      totalsBuffer_.upload(nullptr, TOTAL_COUNT * sizeof(std::uint32_t));
      buffersAllocated_ = true;
    }
    const std::uint32_t zero = 0;
    glClearNamedBufferSubData(recordsBuffer_.id(), GL_R32UI, 0, 16, GL_RED_INTEGER,
                              GL_UNSIGNED_INT, &zero);
    glClearNamedBufferData(totalsBuffer_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kTraceRecords, recordsBuffer_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kTraceTotals, totalsBuffer_.id());

    // 3. Inputs.
    glBindTextureUnit(TRACE_WS_POSITION_UNIT, frame.input(*this, "wsPosition").id());
    glBindTextureUnit(TRACE_WS_NORMAL_UNIT, frame.input(*this, "wsNormal").id());
    glBindTextureUnit(TRACE_NEAR_UNIT, nearLayer.id());
    bindTextureForReading(TRACE_FAR_UNIT, frame.input(*this, "far"));
    bindTextureForReading(minmax ? TRACE_MINMAX_UNIT : TRACE_LEVELS_UNIT, levels);
    bindTextureForReading(TRACE_MASK_UNIT, frame.input(*this, "mask"));
    bindTextureForReading(TRACE_ZRANGE_UNIT, frame.input(*this, "zRange"));

    // 4. The pass.
    const bool recording = params.record.x >= 0 && params.record.y >= 0;
    if (deferred) {
      runDeferred(frame, visibility, cost, deferred_[specialization(params, frame, false, cost)],
                  recording ? &deferred_[specialization(params, frame, true, cost)] : nullptr);
    } else {
      runForward(frame, visibility, *cost,
                 forward_[specialization(params, frame, recording, cost)]);
    }

    // 5. Totals and the recorded steps, read after the frame (Frame::readAfterFrame).
    frame.readAfterFrame(totalsBuffer_, 0, TOTAL_COUNT * sizeof(std::uint32_t),
                         [](const std::vector<unsigned char>& bytes, Frame& frame) {
                           std::uint32_t totals[TOTAL_COUNT];
                           std::memcpy(totals, bytes.data(), sizeof totals);
                           addTotals(totals, frame);
                         });
    readRecords(frame);
  }

private:
  static void addTotals(const std::uint32_t* totals, Frame& frame) {
    const char* names[] = {"rays", "raysSearched", "fetches", "iterations", "earlyOutBackface",
                           "earlyOutInside", "earlyOutRegion", "iterationCapReached"};
    for (int i = 0; i <= TOTAL_ITERATION_CAP; ++i)
      frame.counters["trace." + std::string(names[i])] = totals[i];
    frame.counters["trace.fetchesPerRay"] =
        totals[TOTAL_RAYS] ? double(totals[TOTAL_FETCHES]) / totals[TOTAL_RAYS] : 0.0;
    // The fetches split (thesis §3.7): those of the early-out tests (the end point inside a
    // solid, the ray's region empty), per ray set up; those of the searches, per ray
    // searched; the two add up to trace.fetches.
    const std::uint32_t earlyOutFetches = totals[TOTAL_EARLY_OUT_FETCHES];
    const std::uint32_t searchFetches = totals[TOTAL_FETCHES] - earlyOutFetches;
    frame.counters["trace.fetchesEarlyOuts"] = earlyOutFetches;
    frame.counters["trace.fetchesSearches"] = searchFetches;
    frame.counters["trace.earlyOutFetchesPerRay"] =
        totals[TOTAL_RAYS] ? double(earlyOutFetches) / totals[TOTAL_RAYS] : 0.0;
    frame.counters["trace.searchFetchesPerSearchedRay"] =
        totals[TOTAL_RAYS_SEARCHED] ? double(searchFetches) / totals[TOTAL_RAYS_SEARCHED] : 0.0;
  }


private:
  static constexpr int kRecordCapacity = 8192;
  static constexpr int kRowsPerBand = 64;

  // With classification, only the pixels classify listed are dispatched (64 per group, in
  // bands for responsiveness); the rest is cleared to "lit" first. Without it, every pixel.
  // Each writes its counts as a record, which trace_totals.comp then adds up into the
  // totals. Then the recorded pixel once more, alone, with its steps (any class).
  // cost: null where nobody asked for it (the pass is compiled without its store).
  void runDeferred(Frame& frame, GlTexture& visibility, GlTexture* cost, ShaderProgram& pass,
                   ShaderProgram* recordingPass) {
    const size_t recordBytes = TRACE_RECORD_UVEC4S * 4 * sizeof(std::uint32_t);
    const size_t partialsBytes = size_t(frame.eyeWidth) * frame.eyeHeight * recordBytes;
    if (partialsBytes != partialsBytes_) partialsBuffer_.upload(nullptr, partialsBytes);
    partialsBytes_ = partialsBytes;
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, TRACE_PARTIALS_BINDING, partialsBuffer_.id());
    pass.use();
    glBindImageTexture(TRACE_VISIBILITY_IMAGE, visibility.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                       GL_R32F);
    if (cost)
      glBindImageTexture(TRACE_COST_IMAGE, cost->id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    std::uint32_t records = 0;
    if (param("use_classification").asBool()) {
      records = dispatchListed(frame, visibility, cost);
    } else {
      glUniform1i(TRACE_PIXELS_LOCATION, TRACE_PIXELS_ALL);
      dispatchRows(frame.eyeWidth, frame.eyeHeight, kImageResults | kBufferResults, kRowsPerBand);
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
      records = std::uint32_t(frame.eyeWidth) * std::uint32_t(frame.eyeHeight);
    }
    totalsProgram_.use();
    glUniform1ui(TRACE_TOTALS_RECORDS_LOCATION, records);
    glUniform1i(TRACE_TOTALS_FROM_LIST_LOCATION, param("use_classification").asBool() ? 1 : 0);
    const std::uint32_t perGroup = 64 * TRACE_TOTALS_RECORDS_PER_INVOCATION;
    if (records > 0) glDispatchCompute((records + perGroup - 1) / perGroup, 1, 1);
    glMemoryBarrier(kBufferResults);
    if (recordingPass) {
      recordingPass->use();
      glUniform1i(TRACE_PIXELS_LOCATION, TRACE_PIXELS_RECORDED);
      glDispatchCompute(1, 1, 1);
      glMemoryBarrier(kImageResults | kBufferResults);
    }
  }

  // One invocation per listed pixel, in as many groups as classify counted (an indirect
  // dispatch: the CPU never waits for the count). Returns the most records it can write.
  std::uint32_t dispatchListed(Frame& frame, GlTexture& visibility, GlTexture* cost) {
    const float one = 1.0f, zeros[4] = {0, 0, 0, 0};
    glClearTexImage(visibility.id(), 0, GL_RED, GL_FLOAT, &one);
    if (cost) glClearTexImage(cost->id(), 0, GL_RGBA, GL_FLOAT, zeros);
    // The list's header holds its length (penumbra + umbra pixels; classify_layout.h).
    const GlBuffer& tracedPixels = frame.inputBuffer(*this, "tracedPixels");
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, CLASSIFY_LIST_BINDING, tracedPixels.id());
    glUniform1i(TRACE_PIXELS_LOCATION, TRACE_PIXELS_LISTED);
    glUniform1i(ROW_OFFSET_LOCATION, 0);
    static_assert(CLASSIFY_TRACE_GROUP == 64);  // trace.comp's 8 x 8 groups
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, tracedPixels.id());
    glDispatchComputeIndirect(CLASSIFY_LIST_DISPATCH_OFFSET);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    glMemoryBarrier(kImageResults | kBufferResults);
    return std::uint32_t(frame.eyeWidth) * std::uint32_t(frame.eyeHeight);
  }

  // Every fragment traces its rays; with a recorded pixel, `pass` is the variant with step
  // records (a fragment pass cannot trace one pixel alone the way the deferred pass does).
  void runForward(Frame& frame, GlTexture& visibility, GlTexture& cost, ShaderProgram& pass) {
    if (forwardDepth_.width() != frame.eyeWidth || forwardDepth_.height() != frame.eyeHeight)
      forwardDepth_ = GlTexture(GL_DEPTH_COMPONENT32F, frame.eyeWidth, frame.eyeHeight);
    glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, visibility.id(), 0);
    glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT1, cost.id(), 0);
    glNamedFramebufferTexture(framebuffer_.id(), GL_DEPTH_ATTACHMENT, forwardDepth_.id(), 0);
    const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(framebuffer_.id(), 2, buffers);
    framebuffer_.checkComplete("trace (forward)");
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    glViewport(0, 0, frame.eyeWidth, frame.eyeHeight);
    const float one[4] = {1, 0, 0, 0}, zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 0, one);
    glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 1, zero);
    glClearNamedFramebufferfi(framebuffer_.id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    pass.use();
    frame.gpuScene.draw(/*includeReceivers=*/true);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glMemoryBarrier(kBufferResults);  // the totals and records; the images are framebuffer writes
  }

  void readRecords(Frame& frame) {
    frame.readBack.erase(kTraceStepsKey);
    if (param("record_x").asInt() < 0 || param("record_y").asInt() < 0) return;
    frame.readAfterFrame(recordsBuffer_, 0, 16 + kRecordCapacity * sizeof(gpu::TraceStep),
                         [](const std::vector<unsigned char>& bytes, Frame& frame) {
                           std::uint32_t header[4];
                           std::memcpy(header, bytes.data(), sizeof header);
                           const std::uint32_t count =
                               std::min<std::uint32_t>(header[0], kRecordCapacity);
                           frame.readBack[kTraceStepsKey].assign(
                               bytes.begin() + 16,
                               bytes.begin() + 16 + count * sizeof(gpu::TraceStep));
                           frame.counters["trace.recordedSteps"] = header[0];
                         });
  }

  // Each pass specialized (shaders/shared/trace_ray.glsl says why) for the hierarchy,
  // search, layer count and sample hash of this run, and compiled without the step records
  // or, for the recorded pixel, with them.
  std::string specialization(const gpu::TraceParams& params, const Frame& frame,
                             bool recording, const GlTexture* cost) const {
    return "#define TRACE_HIERARCHY " + std::to_string(params.limits.z) +
           "\n#define TRACE_SEARCH " + std::to_string(params.config.z) +
           "\n#define TRACE_LAYERS " + std::to_string(params.config.w) +
           "\n#define TRACE_RECORDING " + (recording ? "1" : "0") +
           "\n#define TRACE_COST " + (cost ? "1" : "0") + "\n" +
           hashSpecialization(frame.light.hashKind);
  }
  // Every text specialization() can return.
  static std::vector<std::string> specializations() {
    auto values = [](const char* name, std::vector<int> values) {
      std::vector<std::string> lines;
      for (int value : values)
        lines.push_back(std::string(name) + " " + std::to_string(value) + "\n");
      return lines;
    };
    return defineCombinations(
        {values("#define TRACE_HIERARCHY", {HIERARCHY_NBUFFER, HIERARCHY_MINMAX}),
         values("#define TRACE_SEARCH", {SEARCH_LINEAR, SEARCH_LINEAR_BINARY, SEARCH_HIERARCHICAL}),
         values("#define TRACE_LAYERS", {1, 2, 3}), values("#define TRACE_RECORDING", {0, 1}),
         values("#define TRACE_COST", {0, 1}), hashSpecializations()});
  }
  ShaderVariants deferred_{{{GL_COMPUTE_SHADER, "monte_carlo/trace/trace.comp"}}, specializations()};
  ShaderProgram totalsProgram_{{{GL_COMPUTE_SHADER, "monte_carlo/trace/trace_totals.comp"}}};
  ShaderVariants forward_{
      {{GL_VERTEX_SHADER, "shared/scene.vert"}, {GL_FRAGMENT_SHADER, "monte_carlo/trace/trace_forward.frag"}},
      specializations()};
  GlBuffer paramsBuffer_, recordsBuffer_, totalsBuffer_;
  GlBuffer partialsBuffer_;  // the deferred pass's per-pixel counts (trace_layout.h)
  size_t partialsBytes_ = 0;
  bool buffersAllocated_ = false;
  GlFramebuffer framebuffer_;
  GlTexture forwardDepth_;
};

}  // namespace

std::unique_ptr<Stage> makeTraceStage() { return std::make_unique<TraceStage>(); }
