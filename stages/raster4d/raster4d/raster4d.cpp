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
// Nothing the GPU counts is read back inside the run: the placement of P and the FB, the
// bands, STEP 5's chunks and the budget's verdict are computed on the GPU and reach the
// later passes as indirect commands and GPU-side copies into the parameters; the lists are
// allocated from what the CPU can bound (raster4d_gpu.h, raster4dListBounds); the counts for
// people are read after the frame (Frame::readAfterFrame).
// Receivers and occluders follow the reference's conventions (origin offset along the
// normal, receiver-only objects cast nothing, samples behind the tangent plane blocked).
#include <cstddef>
#include <cstring>
#include <algorithm>
#include <stdexcept>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <utility>
#include <memory>

#include "core/frame.h"
#include "core/pipeline.h"
#include "core/run_control.h"
#include "gl/shader_program.h"
#include "raster4d_gpu.h"
#include "shared_inputs/light/light_input.h"
#include "reference/reference_trace.h"

namespace {

using Clock = std::chrono::steady_clock;

// llvmpipe (gallivm) ends every loop of an invocation once the loops of its SIMD batch have run
// 65535 iterations in all, silently (docs/decisions/033-llvmpipe-loop-limit.md): every pass keeps
// its loop iterations per invocation under this budget by splitting its work over dispatches.
constexpr int kLoopBudget = 20000;

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
                                      "beyond it the FB is processed in bands of rows. The lists "
                                      "are allocated at this size (less when fewer entries can "
                                      "occur, more when one FB row may hold more).",
                       1 << 24, 1024, 1 << 28),
        Param::real("budget", "Millions of STEP 5 pair loops a run may take: the (sample, "
                              "triangle) pairs of every FB pixel, known exactly after STEP 4's "
                              "counts, times the loops per pair (m + 1 with row masks, else "
                              "m (m + 1) + 1); over it STEP 5 does not run and the run is "
                              "refused (the window asks). 0: no limit.", 50000.0, 0.0, 1e9),
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
    times_.start(frame);
    occluders_.update(frame.scene);
    gpu::Raster4dParams params = baseParams(frame, m, fb);
    // STEP 2: receivers in light space, their Proj4 bounds on P; then P and the FB placed
    // from the bounds on the GPU (raster4d_place.comp), copied into every later upload of
    // the parameters (upload): nothing here waits for the GPU.
    gpu::Raster4dState state{};
    state.boundsMin = glm::uvec4(~0u);
    state_.upload(&state, sizeof state);
    placed_ = false;
    ensureBufferBytes(receivers_, pixels * sizeof(glm::vec4));
    bind({{R4D_RECEIVERS_RECEIVERS, &receivers_}, {R4D_RECEIVERS_STATE, &state_}});
    upload(params);
    glBindTextureUnit(0, frame.input(*this, "wsPosition").id());
    glBindTextureUnit(1, frame.input(*this, "wsNormal").id());
    receiversProgram_.use();
    dispatchGrid(w, h);
    placeProgram_.use();
    bind({{R4D_PLACE_STATE, &state_}});
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(kBufferResults);
    placed_ = true;
    times_.mark(kStep2);

    // STEP 3: samples to FB pixels (counts, prefix sum; scattered per band below). Without a
    // receiver every count stays 0 (raster4d_triangles.comp returns), so the plan has no band.
    GlBuffer& masks = frame.outputBuffer(*this, "masks");
    ensureBufferBytes(masks, pixels * m * words * sizeof(std::uint32_t));
    zeroBuffer(masks, pixels * m * words * sizeof(std::uint32_t));
    for (GlBuffer* buffer : {&sampleCounts_, &triangleCounts_, &sampleCursors_, &triangleCursors_})
      ensureBufferBytes(*buffer, cells * sizeof(std::uint32_t));
    ensureBufferBytes(cellPairs_, cells * sizeof(glm::uvec4));
    for (GlBuffer* buffer : {&sampleStarts_, &triangleStarts_})
      ensureBufferBytes(*buffer, (cells + 1) * sizeof(std::uint32_t));
    for (GlBuffer* buffer : {&sampleCounts_, &triangleCounts_, &sampleCursors_, &triangleCursors_})
      zeroBuffer(*buffer, cells * sizeof(std::uint32_t));
    zeroBuffer(cellPairs_, cells * sizeof(glm::uvec4));
    const int windowRows = std::max(1, kLoopBudget / (fb + 1));
    samplesProgram_.use();
    bindSamplesPass();
    glUniform1i(0, 0);
    countInWindows(params, fb, windowRows, [&] { dispatchGrid(w, h); });
    scan(sampleCounts_, sampleStarts_, params, cells);
    times_.mark(kStep3);

    // STEP 4: triangles to FB pixels (counts, prefix sum).
    ensureBufferBytes(lsTriangles_, size_t(std::max(1, occluders_.triangles())) * 3 * sizeof(glm::vec4));
    ensureBufferBytes(boxes_, size_t(std::max(1, occluders_.triangles())) * sizeof(glm::vec4));
    trianglesProgram_.use();
    bindTrianglesPass();
    glUniform1i(0, 0);
    countInWindows(params, fb, windowRows,
                   [&] { dispatchLinear(std::uint64_t(occluders_.triangles())); });
    scan(triangleCounts_, triangleStarts_, params, cells);

    // The plan (raster4d_plan.comp): STEP 5's pairs from STEP 3-4's counts (every sample of
    // an FB pixel meets every triangle of its list, so they are known exactly; equal to
    // raster4d.pairsConsidered after the run), the budget, the bands and the chunks, with the
    // indirect commands of every band slot. Over raster4d.budget, nothing after the plan
    // runs and the run is refused after the frame (core/run_control.h).
    const int loopsPerPair = param("row_masks").asBool() ? m + 1 : m * (m + 1) + 1;
    const int chunk = std::max(1, (kLoopBudget - 4 * m) / loopsPerPair);
    const Raster4dListBounds bounds = raster4dListBounds(
        w, h, fb, occluders_.triangles(), param("sample_assignment").asEnum() == "L0",
        std::uint64_t(param("max_entries").asInt()), windowRows, chunk);
    ensureBufferBytes(sampleList_, size_t(bounds.sampleCapacity) * sizeof(glm::uvec2));
    ensureBufferBytes(triangleList_, size_t(bounds.triangleCapacity) * sizeof(std::uint32_t));
    ensureBufferBytes(plan_, sizeof(gpu::Raster4dPlan) + size_t(bounds.bandSlots) * sizeof(gpu::Raster4dBandPlan));
    ensureBufferBytes(step5Commands_, size_t(bounds.bandSlots) * bounds.step5Commands * sizeof(glm::uvec4));
    params.dispatch = glm::ivec4(0, 0, 0, chunk);
    params.options.y = param("max_entries").asInt();
    params.options.z = windowRows;
    params.options.w = bounds.bandSlots;
    const double budget = param("budget").asFloat();
    const double mostPairs = mostPairsWithin(budget, loopsPerPair);
    std::uint64_t mostPairsBits = 0;
    std::memcpy(&mostPairsBits, &mostPairs, sizeof mostPairs);
    params.budget = glm::uvec4(std::uint32_t(mostPairsBits), std::uint32_t(mostPairsBits >> 32),
                               budget > 0 ? 1u : 0u, std::uint32_t(bounds.step5Commands));
    upload(params);
    planProgram_.use();
    bind({{R4D_PLAN_SAMPLE_COUNTS, &sampleCounts_}, {R4D_PLAN_TRIANGLE_COUNTS, &triangleCounts_},
          {R4D_PLAN_SAMPLE_STARTS, &sampleStarts_}, {R4D_PLAN_TRIANGLE_STARTS, &triangleStarts_},
          {R4D_PLAN_STATE, &state_}, {R4D_PLAN_PLAN, &plan_}, {R4D_PLAN_STEP5_COMMANDS, &step5Commands_}});
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(kBufferResults | kCommandResults);
    times_.mark(kStep4);
    throwIfRunCancelled("in raster4d, before STEP 5");

    // Per band slot (the plan's; a slot past the last band has zero commands): STEP 3 and
    // STEP 4 scatter the band's rows (each FB pixel's cursor is used by its own band only,
    // so the cursors are zeroed once), then STEP 5 tests the band's pairs.
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, plan_.id());
    for (int slot = 0; slot < bounds.bandSlots; ++slot) {
      bandSlot_ = slot;
      upload(params);
      samplesProgram_.use();
      bindSamplesPass();
      glUniform1i(0, 1);
      glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, plan_.id());
      glDispatchComputeIndirect(slotOffset(slot) + GLintptr(offsetof(gpu::Raster4dBandPlan, samplesCommand)));
      glMemoryBarrier(kBufferResults);
      times_.mark(kStep3);
      trianglesProgram_.use();
      bindTrianglesPass();
      glUniform1i(0, 1);
      glDispatchComputeIndirect(slotOffset(slot) + GLintptr(offsetof(gpu::Raster4dBandPlan, trianglesCommand)));
      glMemoryBarrier(kBufferResults);
      times_.mark(kStep4);
      occlusionPrograms_[samplesDefine(m)].use();
      bind({{R4D_OCCLUSION_RECEIVERS, &receivers_}, {R4D_OCCLUSION_LS_TRIANGLES, &lsTriangles_},
            {R4D_OCCLUSION_BOXES, &boxes_}, {R4D_OCCLUSION_SAMPLE_LIST, &sampleList_},
            {R4D_OCCLUSION_TRIANGLE_STARTS, &triangleStarts_},
            {R4D_OCCLUSION_TRIANGLE_LIST, &triangleList_}, {R4D_OCCLUSION_MASKS, &masks},
            {R4D_OCCLUSION_CELL_PAIRS, &cellPairs_}});
      glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, step5Commands_.id());
      for (int k = 0; k < bounds.step5Commands; ++k) {
        glUniform1i(R4D_OCCLUSION_CHUNK_BASE_LOCATION, k * RASTER4D_MAX_GROUPS);
        glDispatchComputeIndirect(GLintptr((size_t(slot) * bounds.step5Commands + k) * sizeof(glm::uvec4)));
        glMemoryBarrier(kBufferResults);
      }
      times_.mark(kStep5);
    }
    bandSlot_ = -1;
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);

    // Visibility from the masks; the picked pixel's mask; the FB views.
    upload(params);
    GlTexture& visibility = frame.output(*this, "visibility", w, h);
    GlTexture& mask = frame.output(*this, "pickedMask", m, m);
    glClearTexImage(mask.id(), 0, GL_RED, GL_FLOAT, nullptr);
    resolvePrograms_[samplesDefine(m)].use();
    bind({{R4D_RESOLVE_RECEIVERS, &receivers_}, {R4D_RESOLVE_MASKS, &masks}});
    glBindImageTexture(0, visibility.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    glBindImageTexture(1, mask.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    dispatchGrid(w, h);
    times_.mark(kResolve);
    writeCellViews(frame, fb);
    writeCounters(frame, cells, loopsPerPair, m, fb, budget, bounds);
  }

private:
  enum Step { kStep2, kStep3, kStep4, kStep5, kResolve, kSteps };

  // Per-step milliseconds, by the pipeline's own timing method (docs/decisions/
  // 021-stage-timings.md): with timer queries, a GL_TIMESTAMP query at the end of every
  // step, its result written by the GPU into a buffer (GL_QUERY_BUFFER) and read after the
  // frame; otherwise (llvmpipe, whose query values are wrong, and where the pipeline waits
  // after every stage anyway) glFinish and the steady clock.
  class StepTimes {
  public:
    void start(Frame& frame) {
      queries_ = frame.pipeline.timingMethod() == "GL_TIME_ELAPSED";
      steps_.clear();
      used_ = 0;
      ms_.assign(kSteps, 0.0);
      start_ = Clock::now();
      if (queries_) counter();
    }
    void mark(Step step) {
      if (queries_) {
        steps_.push_back(step);
        counter();
        return;
      }
      glFinish();
      const auto now = Clock::now();
      ms_[step] += std::chrono::duration<double, std::milli>(now - start_).count();
      start_ = now;
    }
    // Fills raster4d.<name> for every step (after the frame with queries).
    void write(Frame& frame) {
      static const char* names[kSteps] = {"step2Ms", "step3Ms", "step4Ms", "step5Ms", "resolveMs"};
      if (!queries_) {
        for (int i = 0; i < kSteps; ++i) frame.counters[std::string("raster4d.") + names[i]] = ms_[i];
        return;
      }
      frame.readAfterFrame(results_, 0, GLsizeiptr(used_ * sizeof(GLuint64)),
                           [steps = steps_](const std::vector<unsigned char>& bytes, Frame& frame) {
                             std::vector<double> ms(kSteps, 0.0);
                             for (size_t i = 0; i < steps.size(); ++i) {
                               GLuint64 from = 0, to = 0;
                               std::memcpy(&from, bytes.data() + i * sizeof from, sizeof from);
                               std::memcpy(&to, bytes.data() + (i + 1) * sizeof to, sizeof to);
                               ms[steps[i]] += double(to - from) * 1e-6;
                             }
                             for (int i = 0; i < kSteps; ++i)
                               frame.counters[std::string("raster4d.") + names[i]] = ms[i];
                           });
    }
    StepTimes() = default;
    StepTimes(const StepTimes&) = delete;
    StepTimes& operator=(const StepTimes&) = delete;
    ~StepTimes() {
      if (!ids_.empty()) glDeleteQueries(GLsizei(ids_.size()), ids_.data());
    }

  private:
    void counter() {
      if (used_ == 0) ensureBufferBytes(results_, capacity_ * sizeof(GLuint64));
      if (used_ == ids_.size()) {
        ids_.resize(ids_.size() + 64);
        glCreateQueries(GL_TIMESTAMP, 64, ids_.data() + ids_.size() - 64);
      }
      if (used_ == capacity_) throw std::logic_error("raster4d: more step marks than the timing buffer holds");
      glQueryCounter(ids_[used_], GL_TIMESTAMP);
      glBindBuffer(GL_QUERY_BUFFER, results_.id());
      glGetQueryObjectui64v(ids_[used_], GL_QUERY_RESULT,
                            reinterpret_cast<GLuint64*>(used_ * sizeof(GLuint64)));
      glBindBuffer(GL_QUERY_BUFFER, 0);
      ++used_;
    }
    bool queries_ = false;
    std::vector<GLuint> ids_;
    std::vector<Step> steps_;
    std::vector<double> ms_;
    Clock::time_point start_;
    GlBuffer results_;
    size_t used_ = 0, capacity_ = 3 * 512 + 8;  // marks: 2 + 3 per band slot (at most 512) + 1
  };

  // The most (sample, triangle) pairs within `budgetMillions` of STEP 5 loops, by the
  // comparison checkRunBudget makes (core/run_control.cpp): the largest whole P with
  // !(P x loopsPerPair x 1e-6 > budget); a huge value when there is no limit.
  static double mostPairsWithin(double budgetMillions, int loopsPerPair) {
    if (budgetMillions <= 0) return 1e300;
    auto refused = [&](double pairs) { return pairs * loopsPerPair * 1e-6 > budgetMillions; };
    double pairs = std::floor(budgetMillions * 1e6 / loopsPerPair);
    for (int i = 0; i < 8 && pairs > 0 && refused(pairs); ++i) pairs -= 1;
    for (int i = 0; i < 8 && !refused(pairs + 1); ++i) pairs += 1;
    return pairs;
  }

  static GLintptr slotOffset(int slot) {
    return GLintptr(sizeof(gpu::Raster4dPlan) + size_t(slot) * sizeof(gpu::Raster4dBandPlan));
  }

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

  // The count passes, over windows of FB rows small enough for the loop budget.
  template <typename Dispatch>
  void countInWindows(gpu::Raster4dParams& params, int fb, int windowRows, Dispatch dispatch) {
    for (int first = 0; first < fb; first += windowRows) {
      params.band = glm::ivec4(first, std::min(fb, first + windowRows), 0, 0);
      upload(params);
      dispatch();
    }
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
  // after the early rejection, really occluding (relevant), milliseconds per step. Every
  // count the GPU made (the state's, the plan's, the pairs per FB pixel) is read after the
  // frame; the plan's read also refuses a run over raster4d.budget (STEP 5 did not run).
  void writeCounters(Frame& frame, size_t cells, int loopsPerPair, int m, int fb, double budget,
                     const Raster4dListBounds& bounds) {
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
    const int triangles = occluders_.triangles();
    const int bandSlots = bounds.bandSlots;
    const bool rowMasks = param("row_masks").asBool();
    frame.readAfterFrame(plan_, 0, sizeof(gpu::Raster4dPlan),
                         [=](const std::vector<unsigned char>& bytes, Frame& frame) {
                           gpu::Raster4dPlan plan{};
                           std::memcpy(&plan, bytes.data(), sizeof plan);
                           readPlan(plan, frame, loopsPerPair, m, fb, triangles, budget, bandSlots,
                                    rowMasks);
                         });
    frame.counters["raster4d.occluders"] = triangles;
    times_.write(frame);
  }

  // The plan's counters, and the budget's verdict (the GPU skipped STEP 5 when over it).
  static void readPlan(const gpu::Raster4dPlan& plan, Frame& frame, int loopsPerPair, int m,
                       int fb, int triangles, double budget, int bandSlots, bool rowMasks) {
    std::uint64_t bits = (std::uint64_t(plan.pairs.y) << 32) | plan.pairs.x;
    double pairs = 0;
    std::memcpy(&pairs, &bits, sizeof pairs);
    auto& c = frame.counters;
    c["raster4d.estimatedPairs"] = pairs;
    c["raster4d.estimatedLoops"] = pairs * loopsPerPair;
    c["raster4d.samplesStored"] = plan.totals.z;
    c["raster4d.triangleEntries"] = plan.totals.w;
    c["raster4d.bands"] = plan.totals.x;
    c["raster4d.step5Chunks"] = plan.totals.y;
    if (plan.totals.x > std::uint32_t(bandSlots))
      throw std::logic_error("raster4d: the plan made " + std::to_string(plan.totals.x) +
                             " bands, more than the " + std::to_string(bandSlots) +
                             " slots bounded for it (raster4dListBounds)");
    const bool ran = plan.pairs.z != 0;
    if (ran) {
      if (budget > 0 && pairs * loopsPerPair * 1e-6 > budget)
        throw std::logic_error("raster4d: STEP 5 ran over raster4d.budget");
      return;
    }
    // Refused: nothing of this run's raster4d, nor of the stages after it that read it, is
    // left to read (STEP 5 never ran; the outputs after it were made from its zero masks).
    for (const char* name : {"visibility", "pickedMask", "fbTriangles", "fbSamples", "fbPairs"})
      frame.textures.erase(std::string("raster4d.") + name);
    frame.buffers.erase("raster4d.masks");
    for (const std::string& output : frame.pipeline.allOutputs()) {
      const std::vector<std::string> producers = frame.pipeline.dependencies({output});
      if (std::find(producers.begin(), producers.end(), "raster4d") != producers.end())
        frame.textures.erase(output);
    }
    char what[160];
    std::snprintf(what, sizeof what, "test %.3g (sample, triangle) pairs x %d loops each in STEP 5 "
                  "(m=%d, %d occluder triangles, FB %d x %d)", pairs, loopsPerPair, m,
                  triangles, fb, fb);
    checkRunBudget("raster4d.budget", pairs * loopsPerPair * 1e-6, budget, what,
                   rowMasks ? "Lower raster4d.samples or the image size"
                            : "Turn raster4d.row_masks on (m + 1 loops per pair), or lower "
                              "raster4d.samples or the image size");
    throw std::logic_error("raster4d: STEP 5 was skipped within raster4d.budget");
  }

  // Each pass's storage buffers at its own bindings (stages/raster4d/raster4d/raster4d_layout.h).
  static void bind(std::initializer_list<std::pair<GLuint, const GlBuffer*>> buffers) {
    for (const auto& [binding, buffer] : buffers)
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, buffer->id());
  }
  void bindSamplesPass() const {
    bind({{R4D_SAMPLES_RECEIVERS, &receivers_}, {R4D_SAMPLES_COUNTS, &sampleCounts_},
          {R4D_SAMPLES_STARTS, &sampleStarts_}, {R4D_SAMPLES_CURSORS, &sampleCursors_},
          {R4D_SAMPLES_LIST, &sampleList_}});
  }
  void bindTrianglesPass() const {
    bind({{R4D_TRIANGLES_TRIANGLES, &occluders_.buffer()}, {R4D_TRIANGLES_LS_TRIANGLES, &lsTriangles_},
          {R4D_TRIANGLES_BOXES, &boxes_}, {R4D_TRIANGLES_STATE, &state_},
          {R4D_TRIANGLES_COUNTS, &triangleCounts_}, {R4D_TRIANGLES_STARTS, &triangleStarts_},
          {R4D_TRIANGLES_CURSORS, &triangleCursors_}, {R4D_TRIANGLES_LIST, &triangleList_}});
  }
  // The CPU's parameters, then, copied on the GPU over them (no wait): once STEP 2 is
  // placed, the plane's D and tolerance and the FB from the state; inside a band slot, the
  // slot's band and dispatch from the plan (stages/raster4d/raster4d/raster4d_layout.h).
  void upload(const gpu::Raster4dParams& params) {
    paramsBuffer_.upload(&params, sizeof params);
    if (placed_) {
      glCopyNamedBufferSubData(state_.id(), paramsBuffer_.id(), offsetof(gpu::Raster4dState, plane),
                               offsetof(gpu::Raster4dParams, plane), 2 * sizeof(float));
      glCopyNamedBufferSubData(state_.id(), paramsBuffer_.id(), offsetof(gpu::Raster4dState, fb),
                               offsetof(gpu::Raster4dParams, fb), sizeof(glm::vec4));
    }
    if (bandSlot_ >= 0) {
      const GLintptr slot = slotOffset(bandSlot_);
      glCopyNamedBufferSubData(plan_.id(), paramsBuffer_.id(),
                               slot + GLintptr(offsetof(gpu::Raster4dBandPlan, band)),
                               offsetof(gpu::Raster4dParams, band), sizeof(glm::ivec4));
      glCopyNamedBufferSubData(plan_.id(), paramsBuffer_.id(),
                               slot + GLintptr(offsetof(gpu::Raster4dBandPlan, dispatch)),
                               offsetof(gpu::Raster4dParams, dispatch), sizeof(glm::ivec4));
    }
    glBindBufferBase(GL_UNIFORM_BUFFER, RASTER4D_PARAMS_BINDING, paramsBuffer_.id());
  }
  // The programs that depend on m (SAMPLES sizes their row arrays), built on first use.
  static std::string samplesDefine(int m) { return "#define SAMPLES " + std::to_string(m); }

  Raster4dOccluders occluders_;
  GlBuffer paramsBuffer_, state_, receivers_, lsTriangles_, boxes_, cellPairs_, plan_, step5Commands_;
  GlBuffer sampleCounts_, sampleStarts_, sampleCursors_, sampleList_;
  GlBuffer triangleCounts_, triangleStarts_, triangleCursors_, triangleList_;
  bool placed_ = false;  // upload copies STEP 2's placement (after raster4d_place.comp)
  int bandSlot_ = -1;    // upload copies this band slot's band and dispatch (>= 0)
  StepTimes times_;
  ShaderProgram placeProgram_{{{GL_COMPUTE_SHADER, "raster4d/raster4d/raster4d_place.comp"}}};
  ShaderProgram planProgram_{{{GL_COMPUTE_SHADER, "raster4d/raster4d/raster4d_plan.comp"}}};
  ShaderProgram receiversProgram_{{{GL_COMPUTE_SHADER, "raster4d/raster4d/raster4d_receivers.comp"}}};
  ShaderProgram samplesProgram_{{{GL_COMPUTE_SHADER, "raster4d/raster4d/raster4d_samples.comp"}}};
  ShaderProgram trianglesProgram_{{{GL_COMPUTE_SHADER, "raster4d/raster4d/raster4d_triangles.comp"}}};
  ShaderProgram scanProgram_{{{GL_COMPUTE_SHADER, "raster4d/raster4d/raster4d_scan.comp"}}};
  ShaderProgram cellsProgram_{{{GL_COMPUTE_SHADER, "raster4d/raster4d/raster4d_cells.comp"}}};
  static std::vector<std::string> samplesDefines() {  // every `samples` value's
    std::vector<std::string> defines;
    for (int m = kMinSamples; m <= kMaxSamples; ++m) defines.push_back(samplesDefine(m));
    return defines;
  }
  ShaderVariants occlusionPrograms_{{{GL_COMPUTE_SHADER, "raster4d/raster4d/raster4d_occlusion.comp"}},
                                    samplesDefines()};
  ShaderVariants resolvePrograms_{{{GL_COMPUTE_SHADER, "raster4d/raster4d/raster4d_resolve.comp"}},
                                  samplesDefines()};
};

}  // namespace

std::unique_ptr<Stage> makeRaster4dStage() { return std::make_unique<Raster4dStage>(); }
