// Stage `nbuffer` (thesis §3.5, Fig 3.6): the N-buffer over the light layers, after Décoret
// (2005) with Schwarz & Stamminger's (2007) changes: windows moved to the texel's center
// and three channels (zNearMin, zNearMax, zFarMax). Layout: shaders/shared/nbuffer.glsl.
#include "core/frame.h"
#include "gl/nbuffer_build.h"

namespace {

class NBufferStage final : public Stage {
public:
  NBufferStage() {
    inputs_ = {
        Input::texture("near", "Near layer: zNearMin and zNearMax.", GL_DEPTH_COMPONENT32F),
        Input::texture("far", "Far layer: zFarMax.", GL_R32F),
    };
    outputs_ = {{"levels",
                 "N-buffer: layer n holds min/max light depths over a 2^n x 2^n window "
                 "around each texel (x: min near, y: max near, z: max far). From level 2 "
                 "on, the texels whose window repeats a border window (2^(n-1) wide bands) "
                 "are written only when the levels are shown or exported: nothing reads them.",
                 GL_RGBA32F,
                 {"zNearMin", "zNearMax", "zFarMax", "unused"},
                 {0, 0, 1, Colormap::Gray},
                 kRoleHierarchy}};
  }
  std::string name() const override { return "nbuffer"; }
  std::string summary() const override {
    return "Min/max occluder depths (zNearMin, zNearMax, zFarMax) over growing windows of the "
           "light layers, one level per window size, for fast region queries.";
  }
  std::string thesisSection() const override { return "thesis §3.5"; }

  void run(Frame& frame) override {
    const GlTexture& nearLayer = frame.input(*this, "near");
    const GlTexture& farLayer = frame.input(*this, "far");
    const int count = nbufferLevelCount(nearLayer.width(), nearLayer.height());
    GlTexture& levels =
        frame.output(*this, "levels", nearLayer.width(), nearLayer.height(), count);
    // Demand-driven (docs/decisions/014-outputs-nobody-asked-for.md): the stages after read only
    // the texels holding distinct windows (nbuffer.glsl); the border bands that repeat them are
    // written when someone shows or exports the levels.
    const bool whole = frame.wanted(name() + ".levels");
    builder_.build(nearLayer, farLayer, levels,
                   whole ? NBufferTexels::All : NBufferTexels::Distinct);
    if (!whole) frame.partial.insert(name() + ".levels");
    frame.counters["nbuffer.levels"] = count;
  }

private:
  NBufferBuilder builder_;
};

}  // namespace

std::unique_ptr<Stage> makeNBufferStage() { return std::make_unique<NBufferStage>(); }
