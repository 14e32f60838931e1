// Stage `light_layers` (thesis §3.3): near and far depth layers seen from the projection
// point behind the light (Eq 3.1), occluders only (receivers excluded).
//
// Departure from the thesis: both layers are rendered without face culling. For closed
// meshes this gives exactly the thesis's layers (the nearest surface is a front face, the
// farthest a back face), and it keeps open meshes and zero-thickness sheets (glTF files,
// the `plate` scene) as occluders with near == far instead of losing them from the far layer.
// The far layer is a colour target blended with MAX rather than a depth buffer tested with
// GREATER (the same values; issue 14: the risers pass then changes only sheet texels).
#include "core/frame.h"
#include "shared_inputs/light_input.h"
#include "gl/gpu_layout.h"
#include "gl/shader_program.h"
#include "shared/light_layers_layout.h"

static_assert(RISERS_NEAR_UNIT < gpu::kTextureUnits && RISERS_FAR_IMAGE < gpu::kImageUnits);
static_assert(LIGHT_LAYERS_FAR_LOCATION != LIGHT_LAYERS_FAR_COPY_LOCATION);

namespace {

class LightLayersStage final : public Stage {
public:
  LightLayersStage() {
    outputs_ = {
        {"near", "Nearest occluder: linear light depth in [0,1]; 1 where no occluder.",
         GL_DEPTH_COMPONENT32F, {"lsDepthNear"}, {0, 0, 1, Colormap::Gray}},
        {"far", "Farthest occluder surface: linear light depth; 0 where no occluder. A "
                "zero-thickness sheet's texel reaches down to its neighbours' depths "
                "(close_risers).",
         GL_R32F, {"lsDepthFar"}, {0, 0, 1, Colormap::Gray}},
    };
    inputs_ = {lightInput()};
    params_ = {
        Param::boolean("close_risers",
                       "A zero-thickness sheet's far layer reaches down to its neighbours' "
                       "depths, so rays cannot slip between the steps a tilted sheet makes in "
                       "the map (issue 12: off, a sheet tilted 35 degrees lets 1-4% of the rays "
                       "through its umbra).",
                       true),
    };
  }
  std::string name() const override { return "light_layers"; }
  std::string summary() const override {
    return "Near (nearest surface) and far (farthest surface) depth layers from the light.";
  }
  std::string thesisSection() const override { return "3.3, Eq 3.1"; }

  void run(Frame& frame) override {
    bindLightInput(frame, *this);
    const int size = frame.light.mapSize;
    GlTexture& nearLayer = frame.output(*this, "near", size, size);
    GlTexture& far = frame.output(*this, "far", size, size);
    if (farRasterized_.width() != size) farRasterized_ = GlTexture(GL_R32F, size, size);
    // 1. The near layer: the depth test keeps the nearest surface.
    glNamedFramebufferTexture(framebuffer_.id(), GL_DEPTH_ATTACHMENT, nearLayer.id(), 0);
    glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, 0, 0);
    glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT1, 0, 0);
    glNamedFramebufferDrawBuffer(framebuffer_.id(), GL_NONE);
    drawOccluders(frame, size, program_, [&] {
      glClearNamedFramebufferfi(framebuffer_.id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
      glEnable(GL_DEPTH_TEST);
      glDepthFunc(GL_LESS);
    });
    // 2. The far layer, and its copy as rasterized: colour targets blended with MAX.
    glNamedFramebufferTexture(framebuffer_.id(), GL_DEPTH_ATTACHMENT, 0, 0);
    glNamedFramebufferTexture(framebuffer_.id(),
                              GLenum(GL_COLOR_ATTACHMENT0 + LIGHT_LAYERS_FAR_LOCATION), far.id(), 0);
    glNamedFramebufferTexture(framebuffer_.id(),
                              GLenum(GL_COLOR_ATTACHMENT0 + LIGHT_LAYERS_FAR_COPY_LOCATION),
                              farRasterized_.id(), 0);
    const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(framebuffer_.id(), 2, buffers);
    drawOccluders(frame, size, program_, [&] {
      const float empty[4] = {0, 0, 0, 0};  // far = 0 where no occluder (§3.3)
      glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 0, empty);
      glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 1, empty);
      glDisable(GL_DEPTH_TEST);
      glEnable(GL_BLEND);
      glBlendEquation(GL_MAX);
    });
    glDisable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    // 3. Sheets close their risers (light_layers_risers.frag): the occluders drawn once more,
    //    so only the texels they cover run the pass (the same rasterization, so every sheet
    //    texel is among them; a texel covered twice is written twice with one value).
    glNamedFramebufferTexture(framebuffer_.id(),
                              GLenum(GL_COLOR_ATTACHMENT0 + LIGHT_LAYERS_FAR_COPY_LOCATION), 0, 0);
    glNamedFramebufferDrawBuffer(framebuffer_.id(), GL_COLOR_ATTACHMENT0);
    glBindTextureUnit(RISERS_NEAR_UNIT, nearLayer.id());
    bindImageForReading(RISERS_FAR_IMAGE, farRasterized_);
    glTextureBarrier();
    risers_.use();
    glUniform1i(RISERS_CLOSE_LOCATION, param("close_risers").asBool() ? 1 : 0);
    drawOccluders(frame, size, risers_, [] {});
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
  }

private:
  // Draws the occluders (receivers excluded) with `program` into the framebuffer as set up,
  // after `prepare` (clears and tests); culling off (the departure above).
  template <typename Prepare>
  void drawOccluders(Frame& frame, int size, ShaderProgram& program, Prepare prepare) {
    framebuffer_.checkComplete("light_layers");
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    glViewport(0, 0, size, size);
    prepare();
    glDisable(GL_CULL_FACE);
    program.use();
    frame.gpuScene.draw(/*includeReceivers=*/false);
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }

  ShaderProgram program_{{{GL_VERTEX_SHADER, "scene.vert"},
                          {GL_FRAGMENT_SHADER, "light_layers.frag"}},
                         "#define LIGHT_PASS\n"};
  GlFramebuffer framebuffer_;
  GlTexture farRasterized_;  // the far layer as rasterized, before close_risers
  ShaderProgram risers_{{{GL_VERTEX_SHADER, "scene.vert"},
                         {GL_FRAGMENT_SHADER, "light_layers_risers.frag"}},
                        "#define LIGHT_PASS\n"};
};

}  // namespace

std::unique_ptr<Stage> makeLightLayersStage() { return std::make_unique<LightLayersStage>(); }
