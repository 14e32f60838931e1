// Stage `light_layers` (thesis §3.3): near and far depth layers seen from the projection
// point behind the light (Eq 3.1), occluders only (receivers excluded).
//
// Departure from the thesis: both layers are rendered without face culling. For closed
// meshes this gives exactly the thesis's layers (the nearest surface is a front face, the
// farthest a back face), and it keeps open meshes and zero-thickness sheets (glTF files,
// the `plate` scene) as occluders with near == far instead of losing them from the far layer.
#include "core/frame.h"
#include "shared_inputs/light_input.h"
#include "gl/gpu_layout.h"
#include "gl/shader_program.h"
#include "shared/light_layers_layout.h"

static_assert(gpu::distinctBelow({RISERS_NEAR_UNIT, RISERS_FAR_UNIT}, gpu::kTextureUnits));

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
    renderLayer(frame, frame.output(*this, "near", size, size), GL_LESS, 1.0f);
    if (farRasterized_.width() != size) farRasterized_ = GlTexture(GL_DEPTH_COMPONENT32F, size, size);
    renderLayer(frame, farRasterized_, GL_GREATER, 0.0f);
    // The far layer of sheets closes the risers between texels (light_layers_risers.comp).
    GlTexture& far = frame.output(*this, "far", size, size);
    risers_.use();
    glUniform1i(RISERS_CLOSE_LOCATION, param("close_risers").asBool() ? 1 : 0);
    glBindTextureUnit(RISERS_NEAR_UNIT, frame.output(*this, "near", size, size).id());
    glBindTextureUnit(RISERS_FAR_UNIT, farRasterized_.id());
    glBindImageTexture(RISERS_FAR_IMAGE, far.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    const GLuint groups = GLuint((size + RISERS_BLOCK - 1) / RISERS_BLOCK + 7) / 8;
    glDispatchCompute(groups, groups, 1);
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
  }

private:
  void renderLayer(Frame& frame, GlTexture& target, GLenum depthTest, float clearDepth) {
    glNamedFramebufferTexture(framebuffer_.id(), GL_DEPTH_ATTACHMENT, target.id(), 0);
    glNamedFramebufferDrawBuffer(framebuffer_.id(), GL_NONE);
    framebuffer_.checkComplete("light_layers");
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    glViewport(0, 0, target.width(), target.height());
    glClearNamedFramebufferfi(framebuffer_.id(), GL_DEPTH_STENCIL, 0, clearDepth, 0);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(depthTest);
    glDisable(GL_CULL_FACE);
    program_.use();
    frame.gpuScene.draw(/*includeReceivers=*/false);
    glDepthFunc(GL_LESS);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }

  ShaderProgram program_{{{GL_VERTEX_SHADER, "scene.vert"},
                          {GL_FRAGMENT_SHADER, "light_layers.frag"}},
                         "#define LIGHT_PASS\n"};
  GlFramebuffer framebuffer_;
  GlTexture farRasterized_;  // the far layer as rasterized, before close_risers
  ShaderProgram risers_{{{GL_COMPUTE_SHADER, "light_layers_risers.comp"}}};
};

}  // namespace

std::unique_ptr<Stage> makeLightLayersStage() { return std::make_unique<LightLayersStage>(); }
