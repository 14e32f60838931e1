// Stage `light_layers` (thesis §3.3): near and far depth layers seen from the projection
// point behind the light (Eq 3.1), occluders only (receivers excluded).
//
// Departure from the thesis: both layers are rendered without face culling. For closed
// meshes this gives exactly the thesis's layers (the nearest surface is a front face, the
// farthest a back face), and it keeps open meshes and zero-thickness sheets (glTF files,
// the `plate` scene) as occluders with near == far instead of losing them from the far layer.
// The far pass writes the far layer as a colour target beside its depth buffer (the same
// values; the risers pass then changes only sheet texels:
// docs/decisions/015-far-layer-as-colour.md), and the far surface's slope beside it, which the
// risers pass reads to tell a neighbour on the same sheet from another occluder
// (docs/decisions/115-risers-closed-along-the-sheets-plane.md) and to give a sheet texel the
// depth range of its plane over the texel's footprint, far and near
// (docs/decisions/145-a-sheet-texel-spans-its-footprint.md).
#include "core/frame.h"
#include "shared_inputs/light/light_input.h"
#include "gl/gpu_layout.h"
#include "gl/screen_triangle.h"
#include "gl/shader_program.h"
#include "shared_inputs/light_layers/light_layers_layout.h"

static_assert(gpu::distinctBelow({RISERS_NEAR_UNIT, RISERS_FAR_UNIT, RISERS_SLOPE_UNIT},
                                 gpu::kTextureUnits));
static_assert(LIGHT_LAYERS_FAR_LOCATION == 0 && LIGHT_LAYERS_SLOPE_LOCATION == 1,
              "the far pass's draw buffers below are in this order");

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
                       "the map (off, a sheet tilted 35 degrees lets 1-4% of the rays through "
                       "its umbra: docs/accuracy.md); its near and far span its plane's depths "
                       "over the texel's footprint.",
                       true),
    };
  }
  LightLayersStage(const LightLayersStage&) = delete;
  LightLayersStage& operator=(const LightLayersStage&) = delete;
  std::string name() const override { return "light_layers"; }
  std::string summary() const override {
    return "Near (nearest surface) and far (farthest surface) depth layers from the light, "
           "in linear light depth.";
  }
  std::string thesisSection() const override { return "thesis §3.3, Eq 3.1"; }

  void run(Frame& frame) override {
    bindLightInput(frame, *this);
    const int size = frame.light.mapSize;
    GlTexture& nearLayer = frame.output(*this, "near", size, size);
    GlTexture& far = frame.output(*this, "far", size, size);
    // 1. The near layer: the depth test keeps the nearest surface.
    glNamedFramebufferTexture(framebuffer_.id(), GL_DEPTH_ATTACHMENT, nearLayer.id(), 0);
    glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, 0, 0);
    glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT1, 0, 0);
    glNamedFramebufferDrawBuffer(framebuffer_.id(), GL_NONE);
    drawOccluders(frame, size, [&] {
      glClearNamedFramebufferfi(framebuffer_.id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
      glEnable(GL_DEPTH_TEST);
      glDepthFunc(GL_LESS);
    });
    // 2. The far layer: the depth test (GREATER) keeps the farthest surface in a depth
    //    buffer, which the risers pass reads, and the fragments that pass it write their
    //    depth to the far layer too, so it holds the same values (a colour target, so the
    //    risers pass need touch only sheet texels), and the slope of their plane to a second
    //    target (light_layers.frag). The slope is read only at sheet texels, which a fragment
    //    always wrote, so it is not cleared.
    if (farRasterized_.width() != size) {
      farRasterized_ = GlTexture(GL_DEPTH_COMPONENT32F, size, size);
      farSlope_ = GlTexture(GL_RG16F, size, size);
      nearRasterized_ = GlTexture(GL_DEPTH_COMPONENT32F, size, size);
    }
    glNamedFramebufferTexture(framebuffer_.id(), GL_DEPTH_ATTACHMENT, farRasterized_.id(), 0);
    glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, far.id(), 0);
    glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT1, farSlope_.id(), 0);
    const GLenum farTargets[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(framebuffer_.id(), 2, farTargets);
    drawOccluders(frame, size, [&] {
      const float empty[4] = {0, 0, 0, 0};  // far = 0 where no occluder (§3.3)
      glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 0, empty);
      glClearNamedFramebufferfi(framebuffer_.id(), GL_DEPTH_STENCIL, 0, 0.0f, 0);
      glEnable(GL_DEPTH_TEST);
      glDepthFunc(GL_GREATER);
    });
    glDepthFunc(GL_LESS);
    // 3. Sheets close their risers and span their footprint (light_layers_risers.frag) over
    //    the texels the occluders can cover: far as a colour target, near as the depth
    //    written (the depth test passes every fragment), read from a copy of the near pass's
    //    (a neighbour's near must be the rasterized one). The texels it discards, and those
    //    outside the rectangle, keep steps 1 and 2's layers.
    if (!param("close_risers").asBool()) return;
    const auto [origin, extent] = occluderRect(frame, size);
    if (extent.x <= 0 || extent.y <= 0) return;
    // Every texel a sheet texel reads (its 4-neighbours) lies in the rectangle: it has a
    // texel of margin around the occluders' projection.
    glCopyImageSubData(nearLayer.id(), GL_TEXTURE_2D, 0, origin.x, origin.y, 0,
                       nearRasterized_.id(), GL_TEXTURE_2D, 0, origin.x, origin.y, 0, extent.x,
                       extent.y, 1);
    risers_.use();
    glBindTextureUnit(RISERS_NEAR_UNIT, nearRasterized_.id());
    glBindTextureUnit(RISERS_FAR_UNIT, farRasterized_.id());
    glBindTextureUnit(RISERS_SLOPE_UNIT, farSlope_.id());
    glTextureBarrier();
    // Far as the colour, near as the depth (each fragment's, whatever was there).
    screen_.drawRectWithDepth(far, nearLayer, origin, extent);
  }

private:
  // The texels the occluders can cover: their bounding box projected into the map, a texel
  // of margin (a covered texel's centre lies in the projection of the box when every corner
  // is in front of the projection point); the whole map otherwise. On the cube at 2048^2 the
  // risers pass over the whole map cost about 30 ms even with every fragment discarded at
  // once; drawing the occluders again instead cost the dragon (91k triangles) 50 ms more.
  // (A far layer blended with MAX into colour targets, instead of the depth test, cost the
  // dragon at 1024^2 about 35 ms more.)
  static std::pair<glm::ivec2, glm::ivec2> occluderRect(const Frame& frame, int size) {
    const Bounds bounds = frame.scene.bounds(/*occludersOnly=*/true);
    if (bounds.empty()) return {glm::ivec2(0), glm::ivec2(0)};
    glm::vec2 lo(1e30f), hi(-1e30f);
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 p(corner & 1 ? bounds.max.x : bounds.min.x,
                        corner & 2 ? bounds.max.y : bounds.min.y,
                        corner & 4 ? bounds.max.z : bounds.min.z);
      const glm::vec4 clip = frame.light.lightClipFromWorld * glm::vec4(p, 1.0f);
      if (!(clip.w > 0.0f)) return {glm::ivec2(0), glm::ivec2(size)};
      const glm::vec2 texel = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * float(size);
      lo = glm::min(lo, texel), hi = glm::max(hi, texel);
    }
    const glm::ivec2 first = glm::clamp(glm::ivec2(glm::floor(lo)) - 1, 0, size);
    const glm::ivec2 end = glm::clamp(glm::ivec2(glm::ceil(hi)) + 1, 0, size);
    return {first, end - first};
  }

  // Draws the occluders (receivers excluded) into the framebuffer as set up, after `prepare`
  // (clears and tests); culling off (the departure above).
  template <typename Prepare>
  void drawOccluders(Frame& frame, int size, Prepare prepare) {
    framebuffer_.checkComplete("light_layers");
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    glViewport(0, 0, size, size);
    prepare();
    glDisable(GL_CULL_FACE);
    program_.use();
    frame.gpuScene.draw(/*includeReceivers=*/false);
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }

  ShaderProgram program_{{{GL_VERTEX_SHADER, "shared/scene.vert"},
                          {GL_FRAGMENT_SHADER, "shared_inputs/light_layers/light_layers.frag"}},
                         "#define LIGHT_PASS\n"};
  GlFramebuffer framebuffer_;
  GlTexture farRasterized_;  // the far layer as rasterized, before close_risers
  GlTexture farSlope_;       // d(1/z) per texel along x and y of the far surface's plane
  GlTexture nearRasterized_;  // the near layer as rasterized (a copy), which the risers read
  ShaderProgram risers_{{{GL_VERTEX_SHADER, "shared/screen_triangle.vert"},
                         {GL_FRAGMENT_SHADER, "shared_inputs/light_layers/light_layers_risers.frag"}}};
  ScreenTriangle screen_;
};

}  // namespace

std::unique_ptr<Stage> makeLightLayersStage() { return std::make_unique<LightLayersStage>(); }
