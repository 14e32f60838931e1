// Stage `filter` (thesis §3, Fig 3.2): a separable depth-sensitive Gaussian over the
// trace's unfiltered visibility, horizontal then vertical; by default only over the tiles
// where it can change a value (docs/decisions/025-filter-only-non-uniform-tiles.md;
// shaders/monte_carlo/filter/filter_tiles.comp says why that is exact, whatever the weights: a window of equal values
// averages to that value).
#include <cstring>
#include <cmath>
#include <cstddef>

#include "core/frame.h"
#include "gl/gpu_layout.h"
#include "gl/shader_program.h"
#include "shared_inputs/light/light_input.h"
#include "shared/screen_pass_layout.h"
namespace gpu {
#include "monte_carlo/filter/filter_layout.h"
}  // namespace gpu

static_assert(offsetof(gpu::FilterTilesHeader, pixels) == 12);
static_assert(sizeof(gpu::FilterTilesHeader) == 16);  // std430: uint[3] stride 4, then uint
static_assert(gpu::distinctBelow({FILTER_SOURCE_UNIT, FILTER_WS_POSITION_UNIT,
                                  FILTER_WS_NORMAL_UNIT, FILTER_ZRANGE_UNIT},
                                 gpu::kTextureUnits));
static_assert(FILTER_TARGET_IMAGE < gpu::kImageUnits);
// filter.comp's shared rows: 8 rows of 8 + 2 x the largest radius taps, 40 bytes each, within
// the 32 KiB of shared memory every GL 4.5 implementation offers.
static_assert(FILTER_TILE_SIZE * (FILTER_TILE_SIZE + 2 * FILTER_MAX_RADIUS) * 40 <= 32768);
static_assert(gpu::distinctBelow({ROW_OFFSET_LOCATION, FILTER_DIRECTION_LOCATION,
                                  FILTER_RADIUS_LOCATION, FILTER_DEPTH_SCALE_LOCATION,
                                  FILTER_NORMAL_POWER_LOCATION, FILTER_TILED_LOCATION,
                                  FILTER_PLANE_SIGMA_LOCATION, FILTER_PIXEL_ANGLE_LOCATION,
                                  FILTER_PENUMBRA_SCALE_LOCATION},
                                 gpu::kUniformLocations));
static_assert(gpu::distinctBelow({FILTER_TILES_BINDING}, gpu::kStorageBindings));

namespace {

class FilterStage final : public Stage {
public:
  FilterStage() {
    inputs_ = {
        Input::texture("visibility", "The visibility to blur (the trace's, unfiltered).", GL_R32F),
        Input::texture("wsPosition", "Receivers: depth differences weight the taps.", GL_RGBA32F),
        Input::texture("wsNormal", "Receiver normals (normal_sensitive, plane_sigma).", GL_RGBA32F),
        Input::texture("zRange", "Occluder depth bounds per pixel (classify): the penumbra "
                                 "width of penumbra_scale.", GL_RGBA32F),
        lightInput(),
    };
    outputs_ = {
        {"horizontal", "After the horizontal pass.", GL_R32F, {"visibility"},
         {0, 0, 1, Colormap::Gray}},
        {"visibility", "Filtered visibility (both passes).", GL_R32F, {"visibility"},
         {0, 0, 1, Colormap::Gray}, kRoleShadowMethod},
        Output::buffer("tiles", "The 8 x 8 tiles blurred (skip_uniform), after an indirect "
                                "dispatch header (filter_layout.h)."),
    };
    params_ = {
        Param::boolean("enabled", "Blur the shadows (off: the visibility passes through).", true),
        Param::integer("radius", "Filter radius in pixels (sigma = radius / 2).", 4, 0,
                       FILTER_MAX_RADIUS),
        Param::real("depth_scale", "Depth sensitivity per world unit: a sample's weight is "
                                   "divided by 1 + depth_scale x |depth difference| (§3).",
                    20, 0, 1000),
        Param::boolean("normal_sensitive", "Also weight by the normals' agreement, so shadows "
                                           "do not bleed over sharp edges (§3).", true),
        Param::real("plane_sigma",
                    "Geometry: a sample's weight falls as exp(-d^2 / 2 (plane_sigma x pixel)^2), "
                    "d its distance from the centre pixel's tangent plane, pixel the world size "
                    "of one pixel there; 0: off. Keeps the lit top of an occluder from bleeding "
                    "into a contact shadow beside it (a plate 0.06 above the ground: mean "
                    "|error| in shadow 0.35 without it, docs/accuracy.md).",
                    1.0, 0, 100),
        Param::real("penumbra_scale",
                    "Penumbra width: a pair of pixels is blurred with sigma at most penumbra_scale "
                    "x the smaller of their penumbra widths in pixels (PCSS's formula from "
                    "classify's deepest occluder in front of the receiver: the narrowest "
                    "penumbra there); 0: off. Keeps a sharp contact, small-occluder or "
                    "tiny-light shadow sharp.",
                    0.5, 0, 100),
        Param::real("normal_power", "Exponent of max(n_c . n_s, 0) when normal_sensitive.", 8, 1,
                    64),
        Param::boolean("skip_uniform", "Blur only the 8 x 8 tiles whose window (the tile grown "
                                       "by the radius) holds a value other than 0 and 1, or "
                                       "both; every other pixel keeps its value, exactly as "
                                       "the full blur would leave it (off: every pixel).", true),
    };
  }
  std::string name() const override { return "filter"; }
  std::string summary() const override {
    return "Depth-aware separable Gaussian blur of the traced visibility.";
  }
  std::string thesisSection() const override { return "thesis §3, Fig 3.2"; }

  void run(Frame& frame) override {
    const int w = frame.eyeWidth, h = frame.eyeHeight;
    const int radius = param("enabled").asBool() ? param("radius").asInt() : 0;
    const float normalPower =
        param("normal_sensitive").asBool() ? param("normal_power").asFloat() : 0.0f;
    const bool tiled = param("skip_uniform").asBool();
    const GlTexture& source = frame.input(*this, "visibility");
    GlTexture& horizontal = frame.output(*this, "horizontal", w, h);
    GlTexture& filtered = frame.output(*this, "visibility", w, h);
    bindTextureForReading(FILTER_WS_POSITION_UNIT, frame.input(*this, "wsPosition"));
    bindTextureForReading(FILTER_WS_NORMAL_UNIT, frame.input(*this, "wsNormal"));
    if (tiled) {
      // 1. The tiles where the blur can change a value, and an indirect dispatch over them.
      GlBuffer& tiles = frame.outputBuffer(*this, "tiles");
      const int tilesX = (w + FILTER_TILE_SIZE - 1) / FILTER_TILE_SIZE;
      const int tilesY = (h + FILTER_TILE_SIZE - 1) / FILTER_TILE_SIZE;
      const size_t bytes = sizeof(gpu::FilterTilesHeader) + size_t(tilesX) * tilesY * 4;
      GLint64 currentBytes = 0;
      glGetNamedBufferParameteri64v(tiles.id(), GL_BUFFER_SIZE, &currentBytes);
      if (size_t(currentBytes) != bytes) tiles.upload(nullptr, bytes);
      const gpu::FilterTilesHeader empty{{0, 1, 1}, 0};
      glNamedBufferSubData(tiles.id(), 0, sizeof empty, &empty);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, FILTER_TILES_BINDING, tiles.id());
      glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, tiles.id());
      if (radius > 0) {
        tilesProgram_.use();
        glUniform1i(FILTER_RADIUS_LOCATION, radius);
        bindTextureForReading(FILTER_SOURCE_UNIT, source);
        dispatchRows(w, h, kBufferResults | kCommandResults);
      }
      // 2. Every other pixel keeps its value in both passes.
      glCopyImageSubData(source.id(), GL_TEXTURE_2D, 0, 0, 0, 0, horizontal.id(), GL_TEXTURE_2D,
                         0, 0, 0, 0, w, h, 1);
      glCopyImageSubData(source.id(), GL_TEXTURE_2D, 0, 0, 0, 0, filtered.id(), GL_TEXTURE_2D, 0,
                         0, 0, 0, w, h, 1);
    }
    // 3. The two passes: over the listed tiles, or over every pixel.
    program_.use();
    glUniform1i(FILTER_TILED_LOCATION, tiled);
    glUniform1i(FILTER_RADIUS_LOCATION, radius);
    glUniform1f(FILTER_DEPTH_SCALE_LOCATION, param("depth_scale").asFloat());
    glUniform1f(FILTER_NORMAL_POWER_LOCATION, normalPower);
    glUniform1f(FILTER_PLANE_SIGMA_LOCATION, param("plane_sigma").asFloat());
    glUniform1f(FILTER_PENUMBRA_SCALE_LOCATION, param("penumbra_scale").asFloat());
    glUniform1f(FILTER_PIXEL_ANGLE_LOCATION,
                2.0f * std::tan(glm::radians(frame.scene.camera.fovYDegrees) * 0.5f) / float(h));
    bindLightInput(frame, *this);
    bindTextureForReading(FILTER_ZRANGE_UNIT, frame.input(*this, "zRange"));
    pass(source, horizontal, {1, 0}, tiled, w, h);
    pass(horizontal, filtered, {0, 1}, tiled, w, h);
    if (!tiled) {
      frame.counters["filter.pixels"] = double(w) * h;
      return;
    }
    frame.readAfterFrame(frame.outputBuffer(*this, "tiles"), 0, sizeof(gpu::FilterTilesHeader),
                         [](const std::vector<unsigned char>& bytes, Frame& frame) {
                           gpu::FilterTilesHeader listed{};
                           std::memcpy(&listed, bytes.data(), sizeof listed);
                           frame.counters["filter.tiles"] = listed.groups[0];
                           frame.counters["filter.pixels"] = listed.pixels;
                         });
  }

private:
  void pass(const GlTexture& source, GlTexture& target, glm::ivec2 direction, bool tiled, int w,
            int h) {
    bindTextureForReading(FILTER_SOURCE_UNIT, source);
    glBindImageTexture(FILTER_TARGET_IMAGE, target.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    glUniform2i(FILTER_DIRECTION_LOCATION, direction.x, direction.y);
    if (!tiled) return dispatchRows(w, h, kImageResults);
    glDispatchComputeIndirect(0);
    glMemoryBarrier(kImageResults);
  }
  ShaderProgram program_{{{GL_COMPUTE_SHADER, "monte_carlo/filter/filter.comp"}}};
  ShaderProgram tilesProgram_{{{GL_COMPUTE_SHADER, "monte_carlo/filter/filter_tiles.comp"}}};
};

}  // namespace

std::unique_ptr<Stage> makeFilterStage() { return std::make_unique<FilterStage>(); }
