// Stage `classify` (thesis §3.6, Eq 3.3, Fig 3.7-3.8): lit / penumbra / umbra per eye
// pixel from occluder-depth bounds over the region of the light map that the pixel's rays
// can cross, refined iteratively over the hierarchy the trace reads (after Guennebaud et al.
// 2006): the N-buffer (exact bounds over the region) or the min-max mipmap (at most
// classify.minmax_cells aligned cells per axis covering it, 4 by default: conservative,
// docs/decisions/026-classify-follows-trace-hierarchy.md), so a frame builds only one. The
// bounds also feed the trace's ray shortening (§3.7, Fig 3.9).
#include <cstring>
#include <cstddef>

#include "core/frame.h"
#include "shared_inputs/light/light_input.h"
#include "gl/screen_triangle.h"
#include "gl/shader_program.h"

namespace gpu {
#include "shared/classes.h"
#include "monte_carlo/classify/classify_layout.h"
}  // namespace gpu

static_assert(offsetof(gpu::ClassifyCounts, pixels) == 0);
static_assert(sizeof(gpu::ClassifyCounts) == 32);  // std430: uint[8], stride 4
static_assert(CLASS_OUTSIDE + 1 == CLASSIFY_CLASS_COUNT);
static_assert(gpu::distinctBelow({CLASSIFY_WS_POSITION_UNIT, CLASSIFY_WS_NORMAL_UNIT,
                                  CLASSIFY_LEVELS_UNIT, CLASSIFY_MINMAX_UNIT, CLASSIFY_NEAR_UNIT,
                                  CLASSIFY_FAR_UNIT}, gpu::kTextureUnits));
static_assert(CLASSIFY_MASK_UNIT < gpu::kTextureUnits);
static_assert(gpu::distinctBelow({CLASSIFY_COUNTS_BINDING, CLASSIFY_LIST_BINDING},
                                 gpu::kStorageBindings));
static_assert(gpu::distinctBelow({CLASSIFY_ITERATIONS_LOCATION,
                                  CLASSIFY_UMBRA_TEST_LOCATION, CLASSIFY_MINMAX_CELLS_LOCATION},
                                 gpu::kUniformLocations));

namespace {

// The hierarchy of occluder depth bounds: whichever trace.hierarchy chooses (the slot follows
// that choice; app/core/stage.h), so the hierarchy not chosen is not built.
Input hierarchyInput() {
  Input input = Input::choice("levels", "Occluder depth bounds over regions of the light map "
                              "(Eq 3.3): the N-buffer (exact over the region) or the min-max "
                              "mipmap (over the aligned cells covering it, at most "
                              "classify.minmax_cells per axis), as the "
                              "trace's hierarchy.", kRoleHierarchy, "trace.hierarchy", "nbuffer",
                              /*allowNone=*/false);
  input.format = GL_RGBA32F;
  return input;
}

class ClassifyStage final : public Stage {
public:
  ClassifyStage() {
    inputs_ = {
        Input::texture("wsPosition", "Receivers (G-buffer).", GL_RGBA32F),
        Input::texture("wsNormal", "Receiver normals (the bias bound of the umbra test).",
                       GL_RGBA32F),
        hierarchyInput(),
        Input::texture("near", "Near layer (§3.2): level 0 of the min-max mipmap.",
                       GL_DEPTH_COMPONENT32F),
        Input::texture("far", "Far layer (§3.3): level 0 of the min-max mipmap.", GL_R32F),
        lightInput(),
    };
    outputs_ = {
        {"mask", "Class per pixel: 0 background, 1 lit, 2 penumbra, 3 umbra, 4 outside the "
                 "light's frustum.",
         GL_R32F, {"class"}, {0, 0, 4, Colormap::Categorical}},
        {"zRange", "Occluder depth bounds over the region the pixel's rays can cross (linear "
                   "light depth): min near, max near, max far; w: the receiver's depth.",
         GL_RGBA32F, {"zNearMin", "zNearMax", "zFarMax", "receiverLsDepth"},
         {0, 0, 1, Colormap::Gray}},
        Output::buffer("tracedPixels", "The penumbra and umbra pixels, packed, after a header "
                                       "holding their count (classify_layout.h): the trace "
                                       "dispatches only these."),
    };
    params_ = {
        Param::integer("iterations", "Refinements of zNearMin by Eq 3.3: each shrinks the "
                                     "region of the map the rays can cross to the part "
                                     "beyond the current zNearMin (§3.6; two usually suffice).",
                       2, 0, 4),
        Param::boolean("umbra", "Classify umbra (receiver behind zNearMax), as the thesis "
                                "does (§3.6). Exact for a single depth layer; with two layers "
                                "a ray can slip between occluders whose map images touch "
                                "(measured: tests/stages/test_classify.cpp, stacked plates), so it "
                                "is a heuristic there; always off with three layers.", true),
        Param::integer("minmax_cells", "With the min-max mipmap (trace.hierarchy=minmax): the "
                                       "most aligned cells per axis covering a pixel's region, "
                                       "at the finest level where that many suffice. The cover "
                                       "is larger than the region (conservative: some lit or "
                                       "umbra pixels become penumbra); more cells cover it "
                                       "closer, for up to cells^2 fetches (cube 640x480, "
                                       "measured end to end: 4 beat 2, 6 and 8).",
                       4, 2, 8),
    };
  }
  std::string name() const override { return "classify"; }
  std::string summary() const override {
    return "Marks pixels fully lit, fully shadowed or in penumbra (and background or outside "
           "the light's frustum), so rays are traced only in the penumbra.";
  }
  std::string thesisSection() const override { return "thesis §3.6, Eq 3.3"; }

  void run(Frame& frame) override {
    const int w = frame.eyeWidth, h = frame.eyeHeight;
    GlTexture& mask = frame.output(*this, "mask", w, h);
    GlTexture& zRange = frame.output(*this, "zRange", w, h);

    // 1. The class and the bounds per pixel (classify.frag).
    const GlTexture& levels = frame.input(*this, "levels");
    const bool minmax = !levels.isArray();  // the min-max mipmap is 2D, the N-buffer an array
    programs_[std::string("#define CLASSIFY_OVER_MINMAX ") + (minmax ? "1" : "0") + "\n"].use();
    bindLightInput(frame, *this);
    bindTextureForReading(CLASSIFY_WS_POSITION_UNIT, frame.input(*this, "wsPosition"));
    bindTextureForReading(CLASSIFY_WS_NORMAL_UNIT, frame.input(*this, "wsNormal"));
    bindTextureForReading(minmax ? CLASSIFY_MINMAX_UNIT : CLASSIFY_LEVELS_UNIT, levels);
    bindTextureForReading(CLASSIFY_NEAR_UNIT, frame.input(*this, "near"));
    bindTextureForReading(CLASSIFY_FAR_UNIT, frame.input(*this, "far"));
    if (minmax) glUniform1i(CLASSIFY_MINMAX_CELLS_LOCATION, param("minmax_cells").asInt());
    glUniform1i(CLASSIFY_ITERATIONS_LOCATION, param("iterations").asInt());
    // §3.6's umbra rule assumes rays cannot pass between occluders; with three layers
    // (§3.4) they can, so it is off there.
    glUniform1i(CLASSIFY_UMBRA_TEST_LOCATION, param("umbra").asBool() && frame.light.layers < 3);
    // Background pixels keep the values cleared first (classify.frag discards them).
    static_assert(CLASS_BACKGROUND == 0);
    screen_.clearAndDraw({&mask, &zRange}, {glm::vec4(0), glm::vec4(0)});

    // 2. The counts and the list of pixels that need rays (classify_list.comp).
    const gpu::ClassifyCounts zero{};
    counts_.upload(&zero, sizeof zero);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, CLASSIFY_COUNTS_BINDING, counts_.id());
    GlBuffer& tracedPixels = frame.outputBuffer(*this, "tracedPixels");
    const size_t listBytes = CLASSIFY_LIST_HEADER_BYTES + size_t(w) * h * sizeof(std::uint32_t);
    GLint64 currentBytes = 0;
    glGetNamedBufferParameteri64v(tracedPixels.id(), GL_BUFFER_SIZE, &currentBytes);
    if (size_t(currentBytes) != listBytes) tracedPixels.upload(nullptr, listBytes);
    // The header: no pixels yet, and the trace's dispatch (0, 1, 1) groups.
    const std::uint32_t header[4] = {0, 0, 1, 1};
    static_assert(sizeof header == CLASSIFY_LIST_HEADER_BYTES && CLASSIFY_LIST_DISPATCH_OFFSET == 4);
    glNamedBufferSubData(tracedPixels.id(), 0, sizeof header, header);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, CLASSIFY_LIST_BINDING, tracedPixels.id());
    listProgram_.use();
    bindTextureForReading(CLASSIFY_MASK_UNIT, mask);
    dispatchRows(w, h, kBufferResults | kCommandResults);

    frame.readAfterFrame(counts_, 0, sizeof(gpu::ClassifyCounts),
                         [](const std::vector<unsigned char>& bytes, Frame& frame) {
                           gpu::ClassifyCounts counts{};
                           std::memcpy(&counts, bytes.data(), sizeof counts);
                           frame.counters["classify.lit"] = counts.pixels[CLASS_LIT];
                           frame.counters["classify.penumbra"] = counts.pixels[CLASS_PENUMBRA];
                           frame.counters["classify.umbra"] = counts.pixels[CLASS_UMBRA];
                           frame.counters["classify.outside"] = counts.pixels[CLASS_OUTSIDE];
                           frame.counters["classify.background"] = counts.pixels[CLASS_BACKGROUND];
                         });
  }

private:
  // One program per hierarchy (classify.frag says why).
  ShaderVariants programs_{{{GL_VERTEX_SHADER, "shared/screen_triangle.vert"},
                            {GL_FRAGMENT_SHADER, "monte_carlo/classify/classify.frag"}},
                           {"#define CLASSIFY_OVER_MINMAX 0\n", "#define CLASSIFY_OVER_MINMAX 1\n"}};
  ShaderProgram listProgram_{{{GL_COMPUTE_SHADER, "monte_carlo/classify/classify_list.comp"}}};
  ScreenTriangle screen_;
  GlBuffer counts_;
};

}  // namespace

std::unique_ptr<Stage> makeClassifyStage() { return std::make_unique<ClassifyStage>(); }
