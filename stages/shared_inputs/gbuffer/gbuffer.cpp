// Stage `gbuffer` (thesis Algorithm 1, step 1; §3.4): the eye pass of deferred shading.
#include "core/frame.h"
#include "gl/gpu_layout.h"
#include "gl/shader_program.h"
#include "shared_inputs/gbuffer/gbuffer_layout.h"

static_assert(GBUFFER_ALBEDO_ATTACHMENT == 0 && GBUFFER_NORMAL_ATTACHMENT == 1 &&
              GBUFFER_POSITION_ATTACHMENT == 2);  // the order of `colour` below

namespace {

class GBufferStage final : public Stage {
public:
  GBufferStage() {
    outputs_ = {
        {"albedo", "Base colour of the visible surface (alpha: 1 where geometry).", GL_RGBA8,
         {"R", "G", "B", "A"}, {}},
        {"wsNormal", "World-space unit normal, turned towards the eye (w: coverage).",
         GL_RGBA32F, {"nx", "ny", "nz", "coverage"}, {-1, -1, 1, Colormap::Gray}},
        {"wsPosition", "World-space position of the visible surface (w: coverage).",
         GL_RGBA32F, {"x", "y", "z", "coverage"}, {-1, -3, 3, Colormap::Gray}},
        {"depth", "Eye window depth in [0,1] (1: background).", GL_DEPTH_COMPONENT32F,
         {"depth"}, {0, 0.9f, 1, Colormap::Gray}},
    };
  }
  std::string name() const override { return "gbuffer"; }
  std::string summary() const override {
    return "Eye pass: albedo, normal, depth and world position of every visible surface.";
  }
  std::string thesisSection() const override { return "thesis §3.4, Alg. 1"; }

  void run(Frame& frame) override {
    const int w = frame.eyeWidth, h = frame.eyeHeight;
    GLuint colour[3] = {frame.output(*this, "albedo", w, h).id(),
                        frame.output(*this, "wsNormal", w, h).id(),
                        frame.output(*this, "wsPosition", w, h).id()};
    for (GLuint i = 0; i < 3; ++i)
      glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0 + i, colour[i], 0);
    glNamedFramebufferTexture(framebuffer_.id(), GL_DEPTH_ATTACHMENT,
                              frame.output(*this, "depth", w, h).id(), 0);
    const GLenum buffers[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
    glNamedFramebufferDrawBuffers(framebuffer_.id(), 3, buffers);
    framebuffer_.checkComplete("gbuffer");

    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    glViewport(0, 0, w, h);
    const float zero[4] = {0, 0, 0, 0};
    for (int i = 0; i < 3; ++i) glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, i, zero);
    glClearNamedFramebufferfi(framebuffer_.id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    program_.use();
    frame.gpuScene.draw(/*includeReceivers=*/true, GBUFFER_BASE_COLOR_LOCATION);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }

private:
  ShaderProgram program_{{{GL_VERTEX_SHADER, "shared/scene.vert"}, {GL_FRAGMENT_SHADER, "shared_inputs/gbuffer/gbuffer.frag"}}};
  GlFramebuffer framebuffer_;
};

}  // namespace

std::unique_ptr<Stage> makeGBufferStage() { return std::make_unique<GBufferStage>(); }
