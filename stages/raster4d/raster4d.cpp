// Stage `raster4d`: 4D rasterization (Wang, Zhao, Meng, Popescu 2020, §3, Algorithms 1-3).
// For every receiver, the m x m occlusion mask of the light's sample grid, exact for those
// samples: each bit is the answer to "does some occluder triangle cross the segment from
// the receiver to this light sample?", decided by four plane tests, not by a depth map. So
// it is a shadow method and a ground truth at once ("exact" = exact for the grid of cell
// centres, not for the continuous light: it converges to the true visibility only as m
// grows; the reference's `uniform` sampling traces the same points).
//  STEP 1  the G-buffer (stage gbuffer) gives the output samples.
//  STEP 2  the plane P behind every receiver, the FB over the receivers' Proj4 bounds.
//  STEP 3  samples to FB pixels: Algorithm 2 (the pixel of the projection from L0).
//  STEP 4  triangles to every FB pixel of their Proj4 AABB, count -> prefix sum -> scatter.
//  STEP 5  per FB pixel, per (sample, triangle) pair: early rejection, four planes, rows.
// Lists of any length (bands of FB rows when they exceed max_entries): nothing is dropped.
// Receivers and occluders follow the reference's conventions (origin offset along the
// normal, receiver-only objects cast nothing, samples behind the tangent plane blocked).
#include <cstring>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <utility>
#include <memory>

#include "core/frame.h"
#include "core/run_control.h"
#include "gl/shader_program.h"
#include "raster4d_gpu.h"
#include "shared_inputs/light_input.h"
#include "reference/reference_trace.h"

namespace {

using Clock = std::chrono::steady_clock;

// llvmpipe (gallivm) ends every loop of an invocation once the loops of its SIMD batch have run
// 65535 iterations in all, silently (docs/decisions/033-llvmpipe-loop-limit.md): every pass keeps
// its loop iterations per invocation under this budget by splitting its work over dispatches.
constexpr int kLoopBudget = 20000;

// GL_TIME_ELAPSED is wrong on llvmpipe: glFinish + steady clock.
double millisecondsSince(Clock::time_point& start) {
  glFinish();
  const auto now = Clock::now();
  const double ms = std::chrono::duration<double, std::milli>(now - start).count();
  start = now;
  return ms;
}

constexpr int kMinSamples = 8, kMaxSamples = 64;  // raster4d.samples: m per side

class Raster4dStage final : public Stage {
public:
  Raster4dStage() {
    inputs_ = {
        Input::texture("wsPosition", "Receivers: the output samples (STEP 1).", GL_RGBA32F),
        Input::texture("wsNormal", "Receiver normals (origin offset, tangent-plane rule).",
                       GL_RGBA32F),
        lightInput(),  // its CPU copy (frame.light) orients the light rectangle
    };
    outputs_ = {
        {"visibility", "1 - (occluded light samples) / m^2 per pixel: exact for the m x m grid "
                       "of cell centres (not for the continuous light).",
         GL_R32F, {"visibility"}, {0, 0, 1, Colormap::Gray},
         kRoleShadowMethod | kRoleGroundTruth},
        {"pickedMask", "The picked pixel's occlusion mask over the light (column = along the light's "
                 "right, row = along its up): 1 hidden by a triangle, 0.5 behind the "
                 "receiver's own tangent plane, 0 reaching the light.",
         GL_R32F, {"occluded"}, {0, 0, 1, Colormap::Gray}},
        {"fbTriangles", "Triangles per FB pixel (STEP 4: every pixel of a triangle's Proj4 AABB).",
         GL_R32F, {"triangles"}, {0, 0, 64, Colormap::Perceptual, true}},
        {"fbSamples", "Output samples per FB pixel (STEP 3).", GL_R32F, {"samples"},
         {0, 0, 64, Colormap::Perceptual, true}},
        {"fbPairs", "(sample, triangle) pairs per FB pixel tested with the four planes (after "
                  "the early rejection when it is on).",
         GL_R32F, {"pairs"}, {0, 0, 4096, Colormap::Perceptual, true}},
        Output::buffer("masks", "The occlusion masks: per pixel (GL order) m rows of ceil(m/32) "
                                "uint words, bit j of row i = light sample (i, j)."),
    };
    params_ = {
        Param::boolean("enabled", "Run 4D rasterization (seconds per frame on llvmpipe for the "
                                  "engine, so off until asked for; turn it on to show it or to "
                                  "use it as error.method or error.against).", false),
        Param::integer("samples", "m: light samples per side, m x m cell centres (the paper: 8x8 "
                                  "too few, 32x32 consistently good).", 32, kMinSamples, kMaxSamples),
        Param::integer("fb_resolution", "w = h: pixels per side of the frame buffer FB that pairs "
                                        "samples with triangles (Table 6: 128 is best).",
                       128, 8, 512),
        Param::choice("sample_assignment",
                      "L0: each sample to the one FB pixel of its projection from the light "
                      "corner L0 (Algorithm 2); proj4: to every pixel its Proj4 covers "
                      "(Algorithm 1, the redundancy of Table 2).",
                      {"L0", "proj4"}, 0),
        Param::boolean("early_rejection", "Skip a pair unless the sample's Proj4 lies inside the "
                                          "triangle's Proj4 AABB (Algorithm 3 lines 5-6).", true),
        Param::boolean("row_masks", "A whole light row per plane from its split column k (§3.3); "
                                    "off: every light sample tested alone (same bits).", true),
        Param::boolean("row_culling", "Not in the paper: test only the light rows that the "
                                      "triangle's cone from the sample reaches (same bits; off "
                                      "is the paper's Algorithm 3).", true),
        Param::integer("max_entries", "Most list entries (samples, and triangles) held at once; "
                                      "beyond it the FB is processed in bands of rows.",
                       1 << 24, 1024, 1 << 28),
        Param::real("budget", "Millions of STEP 5 pair loops a run may take: the (sample, "
                              "triangle) pairs of every FB pixel, known exactly after STEP 4's "
                              "counts, times the loops per pair (m + 1 with row masks, else "
                              "m (m + 1) + 1); a run over it is refused before STEP 5 (the "
                              "window asks). 0: no limit.", 50000.0, 0.0, 1e9),
        Param::integer("pick_x", "Picked pixel (image column) whose mask the `pickedMask` view "
                                 "shows; "
                                 "-1: none.", -1, -1, 16383),
        Param::integer("pick_y", "Picked pixel (image row, 0 on top); -1: none.", -1, -1, 16383),
    };
    capabilities_ = kCapabilityPicksEyePixel | kCapabilityPickedLightMask;  // pickedMask
  }
  std::string name() const override { return "raster4d"; }
  std::string summary() const override {
    return "4D rasterization (Wang et al.): exact occlusion masks over an m x m light grid, a "
           "shadow method and a GPU ground truth. Off unless raster4d.enabled.";
  }
  std::string thesisSection() const override { return "Wang et al. 2020"; }

  void run(Frame& frame) override {
    if (!param("enabled").asBool()) {
      for (const Output& output : outputs_) {
        frame.textures.erase("raster4d." + output.name);
        frame.buffers.erase("raster4d." + output.name);
      }
      return;
    }
    const int w = frame.eyeWidth, h = frame.eyeHeight, m = param("samples").asInt();
    const int words = (m + 31) / 32, fb = param("fb_resolution").asInt();
    const size_t pixels = size_t(w) * h, cells = size_t(fb) * fb;
    auto start = Clock::now();
    occluders_.update(frame.scene);
    gpu::Raster4dParams params = baseParams(frame, m, fb);
    // STEP 2: receivers in light space, their Proj4 bounds on P.
    gpu::Raster4dState state{};
    state.boundsMin = glm::uvec4(~0u);
    state_.upload(&state, sizeof state);
    ensureBufferBytes(receivers_, pixels * sizeof(glm::vec4));
    bind({{R4D_RECEIVERS_RECEIVERS, &receivers_}, {R4D_RECEIVERS_STATE, &state_}});
    upload(params);
    glBindTextureUnit(0, frame.input(*this, "wsPosition").id());
    glBindTextureUnit(1, frame.input(*this, "wsNormal").id());
    receiversProgram_.use();
    dispatchGrid(w, h);
    // The three waits for the GPU inside this stage's run, each before work whose size or
    // placement it sets on the CPU: here the plane P and the FB window (every later pass's
    // parameters), after STEP 4 the list totals (the lists' buffer sizes, the bands) and the
    // longest triangle list (STEP 5's chunks). The counts for people are read after the frame.
    state = readBuffer<gpu::Raster4dState>(state_, 1)[0];
    placePlane(params, state, fb);
    upload(params);
    const double step2 = millisecondsSince(start);

    // STEP 3: samples to FB pixels (counts, prefix sum; scattered per band below).
    GlBuffer& masks = frame.outputBuffer(*this, "masks");
    ensureBufferBytes(masks, pixels * m * words * sizeof(std::uint32_t));
    zeroBuffer(masks, pixels * m * words * sizeof(std::uint32_t));
    for (GlBuffer* buffer : {&sampleCounts_, &triangleCounts_, &cursors_})
      ensureBufferBytes(*buffer, cells * sizeof(std::uint32_t));
    ensureBufferBytes(cellPairs_, cells * sizeof(glm::uvec4));
    for (GlBuffer* buffer : {&sampleStarts_, &triangleStarts_})
      ensureBufferBytes(*buffer, (cells + 1) * sizeof(std::uint32_t));
    zeroBuffer(sampleCounts_, cells * sizeof(std::uint32_t));
    zeroBuffer(triangleCounts_, cells * sizeof(std::uint32_t));
    zeroBuffer(cellPairs_, cells * sizeof(glm::uvec4));
    const bool anyReceiver = state.counts.x > 0;
    const int windowRows = std::max(1, kLoopBudget / (fb + 1));
    if (anyReceiver) {
      samplesProgram_.use();
      bindSamplesPass();
      glUniform1i(0, 0);
      countInWindows(params, fb, windowRows, [&] { dispatchGrid(w, h); });
      scan(sampleCounts_, sampleStarts_, params, cells);
    }
    double step3 = millisecondsSince(start);

    // STEP 4: triangles to FB pixels (counts, prefix sum).
    ensureBufferBytes(lsTriangles_, size_t(std::max(1, occluders_.triangles())) * 3 * sizeof(glm::vec4));
    ensureBufferBytes(boxes_, size_t(std::max(1, occluders_.triangles())) * sizeof(glm::vec4));
    if (anyReceiver) {
      trianglesProgram_.use();
      bindTrianglesPass();
      glUniform1i(0, 0);
      countInWindows(params, fb, windowRows,
                     [&] { dispatchLinear(std::uint64_t(occluders_.triangles())); });
      scan(triangleCounts_, triangleStarts_, params, cells);
    }
    double step4 = millisecondsSince(start);

    // Before STEP 5, its cost from STEP 3-4's counts: every sample of an FB pixel meets
    // every triangle of its list, so the pairs are known exactly (raster4d.pairsConsidered
    // after the run); refused over the budget (core/run_control.h).
    const int loopsPerPair = param("row_masks").asBool() ? m + 1 : m * (m + 1) + 1;
    const double pairs = anyReceiver ? pairsToTest(cells) : 0;
    frame.counters["raster4d.estimatedPairs"] = pairs;
    frame.counters["raster4d.estimatedLoops"] = pairs * loopsPerPair;
    char what[160];
    std::snprintf(what, sizeof what, "test %.3g (sample, triangle) pairs x %d loops each in STEP 5 "
                  "(m=%d, %d occluder triangles, FB %d x %d)", pairs, loopsPerPair, m,
                  occluders_.triangles(), fb, fb);
    checkRunBudget("raster4d.budget", pairs * loopsPerPair * 1e-6, param("budget").asFloat(), what,
                   param("row_masks").asBool()
                       ? "Lower raster4d.samples or the image size"
                       : "Turn raster4d.row_masks on (m + 1 loops per pair), or lower "
                         "raster4d.samples or the image size");
    throwIfRunCancelled("in raster4d, before STEP 5");

    // Bands of FB rows whose lists fit (one band unless max_entries is exceeded).
    std::vector<Raster4dBand> bands;
    if (anyReceiver)
      bands = plan(fb, windowRows, cells, std::uint64_t(param("max_entries").asInt()));
    // STEP 5 splits each pixel's triangle list into chunks whose loops fit the budget.
    const int chunk = std::max(1, (kLoopBudget - 4 * m) / loopsPerPair);
    const int chunks = anyReceiver ? (mostTrianglesPerPixel(cells) + chunk - 1) / chunk : 0;
    double step5 = 0;
    for (const Raster4dBand& band : bands) {
      params.band = glm::ivec4(band.firstRow, band.endRow, int(band.sampleBase), int(band.triangleBase));
      upload(params);
      // STEP 3, scatter.
      zeroBuffer(cursors_, cells * sizeof(std::uint32_t));
      samplesProgram_.use();
      bindSamplesPass();
      glUniform1i(0, 1);
      dispatchGrid(w, h);
      step3 += millisecondsSince(start);
      // STEP 4, scatter.
      zeroBuffer(cursors_, cells * sizeof(std::uint32_t));
      trianglesProgram_.use();
      bindTrianglesPass();
      glUniform1i(0, 1);
      dispatchLinear(std::uint64_t(occluders_.triangles()));
      step4 += millisecondsSince(start);
      // STEP 5: the band's pairs.
      occlusionPrograms_[samplesDefine(m)].use();
      bind({{R4D_OCCLUSION_RECEIVERS, &receivers_}, {R4D_OCCLUSION_LS_TRIANGLES, &lsTriangles_},
            {R4D_OCCLUSION_BOXES, &boxes_}, {R4D_OCCLUSION_SAMPLE_LIST, &sampleList_},
            {R4D_OCCLUSION_TRIANGLE_STARTS, &triangleStarts_},
            {R4D_OCCLUSION_TRIANGLE_LIST, &triangleList_}, {R4D_OCCLUSION_MASKS, &masks},
            {R4D_OCCLUSION_CELL_PAIRS, &cellPairs_}});
      for (int i = 0; i < chunks; ++i) {
        params.dispatch = glm::ivec4(int(band.sampleEntries), 0, i * chunk, chunk);
        upload(params);
        dispatchLinear(band.sampleEntries);
      }
      step5 += millisecondsSince(start);
    }

    // Visibility from the masks; the picked pixel's mask; the FB views.
    GlTexture& visibility = frame.output(*this, "visibility", w, h);
    GlTexture& mask = frame.output(*this, "pickedMask", m, m);
    glClearTexImage(mask.id(), 0, GL_RED, GL_FLOAT, nullptr);
    resolvePrograms_[samplesDefine(m)].use();
    bind({{R4D_RESOLVE_RECEIVERS, &receivers_}, {R4D_RESOLVE_MASKS, &masks}});
    glBindImageTexture(0, visibility.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    glBindImageTexture(1, mask.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    dispatchGrid(w, h);
    const double resolve = millisecondsSince(start);
    writeCellViews(frame, fb);
    writeCounters(frame, bands, chunks, cells, {step2, step3, step4, step5, resolve});
  }

private:
  gpu::Raster4dParams baseParams(const Frame& frame, int m, int fb) const {
    const AreaLight& light = frame.scene.light;
    const float halfWidth = 0.5f * light.width, halfHeight = 0.5f * light.height;
    const Bounds bounds = frame.scene.bounds();
    const float diagonal = bounds.empty() ? 1.0f : glm::length(bounds.max - bounds.min);
    gpu::Raster4dParams p{};
    p.lsFromWorld = lightSpaceFromWorld(light.center, frame.light.right, frame.light.up,
                                        frame.light.forward);
    const float du = 2 * halfWidth / float(m), dv = 2 * halfHeight / float(m);
    p.light = glm::vec4(halfWidth - 0.5f * du, halfHeight - 0.5f * dv, du, dv);
    // The reference's smallest origin offset (reference_trace.h, "Origin"; the shader adds
    // the relative part), and the nearest depth that still has a bounded Proj4.
    p.plane = glm::vec4(0, 0, referenceMinimumOffset(frame.scene), kRelativeEpsilon * diagonal);
    p.sizes = glm::ivec4(fb, fb, frame.eyeWidth, frame.eyeHeight);
    p.modes = glm::ivec4(param("sample_assignment").asEnum() == "L0" ? RASTER4D_ASSIGN_L0
                                                                      : RASTER4D_ASSIGN_PROJ4,
                         param("early_rejection").asBool(), param("row_masks").asBool(),
                         occluders_.triangles());
    const int pickX = param("pick_x").asInt(), pickY = param("pick_y").asInt();
    p.options = glm::ivec4(param("row_culling").asBool(), 0, 0, 0);
    p.pick = glm::ivec4(pickX, pickY < 0 ? -1 : frame.eyeHeight - 1 - pickY, m, (m + 31) / 32);
    return p;
  }

  // STEP 2 (Fig 2): P at the farthest receiver's depth D; the FB spans the Proj4 bounds,
  // [D (x - a)/d + a, D (x + a)/d - a] per axis (shared/raster4d_layout.h).
  static void placePlane(gpu::Raster4dParams& p, const gpu::Raster4dState& state, int fb) {
    auto decode = [](std::uint32_t bits) {
      return (bits & 0x80000000u) ? glm::uintBitsToFloat(bits & 0x7fffffffu)
                                  : glm::uintBitsToFloat(~bits);
    };
    if (state.counts.x == 0) return;
    const float depth = decode(state.boundsMax.z);
    const glm::vec2 lo = depth * glm::vec2(decode(state.boundsMin.x), decode(state.boundsMin.y)) +
                         glm::vec2(p.light);
    const glm::vec2 hi = depth * glm::vec2(decode(state.boundsMax.x), decode(state.boundsMax.y)) -
                         glm::vec2(p.light);
    const float scale = std::max({std::fabs(lo.x), std::fabs(lo.y), std::fabs(hi.x),
                                  std::fabs(hi.y), hi.x - lo.x, hi.y - lo.y, 1e-6f});
    const glm::vec2 extent = glm::max(hi - lo, glm::vec2(1e-6f * scale));
    // Round-off tolerance: triangle boxes grow by it, so rounding only adds pairs.
    p.plane.x = depth;
    p.plane.y = 1e-5f * scale;
    p.fb = glm::vec4(lo, glm::vec2(float(fb)) / extent);
  }

  // The count passes, over windows of FB rows small enough for the loop budget.
  template <typename Dispatch>
  void countInWindows(gpu::Raster4dParams& params, int fb, int windowRows, Dispatch dispatch) {
    for (int first = 0; first < fb; first += windowRows) {
      params.band = glm::ivec4(first, std::min(fb, first + windowRows), 0, 0);
      upload(params);
      dispatch();
    }
  }

  // Sum over FB pixels of samples x triangles in their lists (STEP 3-4 counts).
  double pairsToTest(size_t cells) const {
    const std::vector<std::uint32_t> samples = readBuffer<std::uint32_t>(sampleCounts_, cells);
    const std::vector<std::uint32_t> triangles = readBuffer<std::uint32_t>(triangleCounts_, cells);
    double pairs = 0;
    for (size_t c = 0; c < cells; ++c) pairs += double(samples[c]) * double(triangles[c]);
    return pairs;
  }

  int mostTrianglesPerPixel(size_t cells) const {
    std::uint32_t most = 0;
    for (std::uint32_t count : readBuffer<std::uint32_t>(triangleCounts_, cells)) most = std::max(most, count);
    return int(most);
  }

  std::vector<Raster4dBand> plan(int fb, int windowRows, size_t cells,
                                 std::uint64_t maxEntries) const {
    const auto sampleTotal = readBuffer<std::uint32_t>(sampleStarts_, 1, cells)[0];
    const auto triangleTotal = readBuffer<std::uint32_t>(triangleStarts_, 1, cells)[0];
    std::vector<Raster4dBand> bands;
    if (sampleTotal <= maxEntries && triangleTotal <= maxEntries && windowRows >= fb)
      bands = {{0, fb, 0, sampleTotal, 0, triangleTotal}};
    else
      bands = planBands(readBuffer<std::uint32_t>(sampleStarts_, cells + 1),
                        readBuffer<std::uint32_t>(triangleStarts_, cells + 1), fb, fb,
                        maxEntries, windowRows);
    std::uint32_t mostSamples = 1, mostTriangles = 1;
    for (const Raster4dBand& band : bands) {
      mostSamples = std::max(mostSamples, band.sampleEntries);
      mostTriangles = std::max(mostTriangles, band.triangleEntries);
    }
    ensureBufferBytes(sampleList_, size_t(mostSamples) * sizeof(glm::uvec2));
    ensureBufferBytes(triangleList_, size_t(mostTriangles) * sizeof(std::uint32_t));
    return bands;
  }

  void scan(const GlBuffer& counts, const GlBuffer& starts, gpu::Raster4dParams& params,
            size_t cells) {
    params.dispatch.y = int(cells);
    upload(params);
    bind({{R4D_SCAN_COUNTS, &counts}, {R4D_SCAN_STARTS, &starts}});
    scanProgram_.use();
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(kBufferResults);
  }

  void writeCellViews(Frame& frame, int fb) {
    cellsProgram_.use();
    bind({{R4D_CELLS_TRIANGLE_COUNTS, &triangleCounts_}, {R4D_CELLS_SAMPLE_COUNTS, &sampleCounts_},
          {R4D_CELLS_PAIRS, &cellPairs_}});
    const char* names[] = {"fbTriangles", "fbSamples", "fbPairs"};
    for (int i = 0; i < 3; ++i)
      glBindImageTexture(GLuint(i), frame.output(*this, names[i], fb, fb).id(), 0, GL_FALSE, 0,
                         GL_WRITE_ONLY, GL_R32F);
    dispatchGrid(fb, fb);
  }

  // Tables 2, 3 and 7 of the paper: samples stored (redundancy), pairs considered, kept
  // after the early rejection, really occluding (relevant), milliseconds per step.
  // The GPU's counts (the state's, the pairs per FB pixel) are read after the frame.
  void writeCounters(Frame& frame, const std::vector<Raster4dBand>& bands, int chunks,
                     size_t cells, const std::vector<double>& ms) const {
    double samplesStored = 0, triangleEntries = 0;
    for (const Raster4dBand& band : bands)
      samplesStored += band.sampleEntries, triangleEntries += band.triangleEntries;
    frame.readAfterFrame(state_, 0, sizeof(gpu::Raster4dState),
                         [](const std::vector<unsigned char>& bytes, Frame& frame) {
                           gpu::Raster4dState state{};
                           std::memcpy(&state, bytes.data(), sizeof state);
                           auto& c = frame.counters;
                           c["raster4d.receivers"] = state.counts.x;
                           c["raster4d.behindLight"] = state.counts.y;
                           c["raster4d.occludersBinned"] = state.counts.z;
                           c["raster4d.occludersCrossingLight"] = state.counts.w;
                         });
    frame.readAfterFrame(cellPairs_, 0, GLsizeiptr(cells * sizeof(glm::uvec4)),
                         [cells](const std::vector<unsigned char>& bytes, Frame& frame) {
                           double considered = 0, kept = 0, occluding = 0;
                           for (size_t i = 0; i < cells; ++i) {
                             glm::uvec4 pairs;
                             std::memcpy(&pairs, bytes.data() + i * sizeof pairs, sizeof pairs);
                             considered += pairs.x, kept += pairs.y, occluding += pairs.z;
                           }
                           frame.counters["raster4d.pairsConsidered"] = considered;
                           frame.counters["raster4d.pairsKept"] = kept;
                           frame.counters["raster4d.pairsOccluding"] = occluding;
                         });
    auto& c = frame.counters;
    c["raster4d.occluders"] = occluders_.triangles();
    c["raster4d.samplesStored"] = samplesStored;
    c["raster4d.triangleEntries"] = triangleEntries;
    c["raster4d.bands"] = double(bands.size());
    c["raster4d.step5Chunks"] = chunks;
    const char* steps[] = {"step2Ms", "step3Ms", "step4Ms", "step5Ms", "resolveMs"};
    for (size_t i = 0; i < ms.size(); ++i) c[std::string("raster4d.") + steps[i]] = ms[i];
  }

  // Each pass's storage buffers at its own bindings (shared/raster4d_layout.h).
  static void bind(std::initializer_list<std::pair<GLuint, const GlBuffer*>> buffers) {
    for (const auto& [binding, buffer] : buffers)
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, buffer->id());
  }
  void bindSamplesPass() const {
    bind({{R4D_SAMPLES_RECEIVERS, &receivers_}, {R4D_SAMPLES_COUNTS, &sampleCounts_},
          {R4D_SAMPLES_STARTS, &sampleStarts_}, {R4D_SAMPLES_CURSORS, &cursors_},
          {R4D_SAMPLES_LIST, &sampleList_}});
  }
  void bindTrianglesPass() const {
    bind({{R4D_TRIANGLES_TRIANGLES, &occluders_.buffer()}, {R4D_TRIANGLES_LS_TRIANGLES, &lsTriangles_},
          {R4D_TRIANGLES_BOXES, &boxes_}, {R4D_TRIANGLES_STATE, &state_},
          {R4D_TRIANGLES_COUNTS, &triangleCounts_}, {R4D_TRIANGLES_STARTS, &triangleStarts_},
          {R4D_TRIANGLES_CURSORS, &cursors_}, {R4D_TRIANGLES_LIST, &triangleList_}});
  }
  void upload(const gpu::Raster4dParams& params) {
    paramsBuffer_.upload(&params, sizeof params);
    glBindBufferBase(GL_UNIFORM_BUFFER, RASTER4D_PARAMS_BINDING, paramsBuffer_.id());
  }
  // The programs that depend on m (SAMPLES sizes their row arrays), built on first use.
  static std::string samplesDefine(int m) { return "#define SAMPLES " + std::to_string(m); }

  Raster4dOccluders occluders_;
  GlBuffer paramsBuffer_, state_, receivers_, lsTriangles_, boxes_, cursors_, cellPairs_;
  GlBuffer sampleCounts_, sampleStarts_, sampleList_, triangleCounts_, triangleStarts_, triangleList_;
  ShaderProgram receiversProgram_{{{GL_COMPUTE_SHADER, "raster4d_receivers.comp"}}};
  ShaderProgram samplesProgram_{{{GL_COMPUTE_SHADER, "raster4d_samples.comp"}}};
  ShaderProgram trianglesProgram_{{{GL_COMPUTE_SHADER, "raster4d_triangles.comp"}}};
  ShaderProgram scanProgram_{{{GL_COMPUTE_SHADER, "raster4d_scan.comp"}}};
  ShaderProgram cellsProgram_{{{GL_COMPUTE_SHADER, "raster4d_cells.comp"}}};
  static std::vector<std::string> samplesDefines() {  // every `samples` value's
    std::vector<std::string> defines;
    for (int m = kMinSamples; m <= kMaxSamples; ++m) defines.push_back(samplesDefine(m));
    return defines;
  }
  ShaderVariants occlusionPrograms_{{{GL_COMPUTE_SHADER, "raster4d_occlusion.comp"}},
                                    samplesDefines()};
  ShaderVariants resolvePrograms_{{{GL_COMPUTE_SHADER, "raster4d_resolve.comp"}},
                                  samplesDefines()};
};

}  // namespace

std::unique_ptr<Stage> makeRaster4dStage() { return std::make_unique<Raster4dStage>(); }
