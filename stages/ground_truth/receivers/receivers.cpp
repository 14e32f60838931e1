// Stage `receivers`: which eye pixels show a receiver-only object (the scene's
// `receiver_only` flag; thesis §3.3). Soft shadow maps keep occluders and receivers apart and
// compute no self-shadowing (Atty et al. 2006 §3), and Atty et al. measure their error on the
// receivers only (§4.2.1: the soft shadow map, projected on the receiver). The error stage's
// `pixels = receivers` counts these pixels alone.
//   1. The scene again from the eye with a depth buffer of its own, the G-buffer's vertex
//      shader and draw order, and its depth test: the surface kept per pixel is the G-buffer's.
//   2. Each object writes its flag: 1 for a receiver-only object, 0 for an occluder (and 0
//      on the background).
// Not part of any method's closure, so no method's timing includes it.
#include "core/frame.h"
#include "gl/gpu_layout.h"
#include "gl/gpu_scene.h"
#include "gl/shader_program.h"
#include "ground_truth/receivers/receivers_layout.h"

static_assert(gpu::distinctBelow({RECEIVERS_FLAG_LOCATION}, gpu::kUniformLocations));

namespace {

class ReceiversStage final : public Stage {
public:
  ReceiversStage() {
    outputs_ = {{"flag", "1 where the visible surface belongs to a receiver-only object (the "
                         "scene's receiver_only flag), 0 on occluders and the background.",
                 GL_R8, {"receiver"}, {0, 0, 1, Colormap::Gray}}};
  }
  std::string name() const override { return "receivers"; }
  std::string summary() const override {
    return "Which eye pixels show a receiver-only object (Atty et al. 2006 measure there).";
  }
  std::string thesisSection() const override { return "Atty et al. 2006 §4.2.1"; }

  void run(Frame& frame) override {
    const int w = frame.eyeWidth, h = frame.eyeHeight;
    if (depth_.width() != w || depth_.height() != h) depth_ = GlTexture(GL_DEPTH_COMPONENT32F, w, h);
    GlTexture& flag = frame.output(*this, "flag", w, h);
    glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, flag.id(), 0);
    glNamedFramebufferTexture(framebuffer_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
    glNamedFramebufferDrawBuffer(framebuffer_.id(), GL_COLOR_ATTACHMENT0);
    framebuffer_.checkComplete("receivers");

    // 1. The G-buffer's pass: same vertex shader, depth test and order of the objects.
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    glViewport(0, 0, w, h);
    const float zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 0, zero);
    glClearNamedFramebufferfi(framebuffer_.id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    program_.use();
    // 2. One flag per object.
    for (const GpuScene::DrawItem& item : frame.gpuScene.items()) {
      glUniform1f(RECEIVERS_FLAG_LOCATION, item.receiverOnly ? 1.0f : 0.0f);
      glBindVertexArray(item.vertexArray);
      glDrawElements(GL_TRIANGLES, item.indexCount, GL_UNSIGNED_INT, nullptr);
    }
    glBindVertexArray(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }

private:
  ShaderProgram program_{{{GL_VERTEX_SHADER, "shared/scene.vert"}, {GL_FRAGMENT_SHADER, "ground_truth/receivers/receivers.frag"}}};
  GlFramebuffer framebuffer_;
  GlTexture depth_;
};

}  // namespace

std::unique_ptr<Stage> makeReceiversStage() { return std::make_unique<ReceiversStage>(); }
