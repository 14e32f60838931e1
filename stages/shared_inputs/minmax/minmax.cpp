// Stage `minmax` (docs/decisions/024-minmax-mipmap-levels.md): the min-max mipmap over the light
// layers, the conventional image pyramid of thesis §5.1's future work ("maximum mipmaps", Tevs et
// al. 2008). Each texel holds (zNearMin, zNearMax, zFarMax) over a quadtree-aligned cell, from its
// 2 x 2 children, as the mip levels of one texture: 1/3 of one level's memory at a power-of-two
// map (level 0 is the layers) where the N-buffer (§3.5) keeps log2(W) + 1 levels. Layout: shaders/shared/minmax.glsl. The trace searches it when
// trace.hierarchy = minmax.
#include "core/frame.h"
#include "shared_inputs/minmax/minmax_build.h"

namespace {

class MinMaxStage final : public Stage {
public:
  MinMaxStage() {
    inputs_ = {
        Input::texture("near", "Near layer: zNearMin and zNearMax.", GL_DEPTH_COMPONENT32F),
        Input::texture("far", "Far layer: zFarMax.", GL_R32F),
    };
    outputs_ = {{"levels",
                 "Min-max mipmap, level n >= 1 as mip level n - 1 (level 0 is the light "
                 "layers, not stored); a level-n texel holds min/max light depths over an "
                 "aligned 2^n x 2^n cell (x: min near, y: max near, z: max far). The base is "
                 "padded to a power of two; padding texels are 0.",
                 GL_RGBA32F,
                 {"zNearMin", "zNearMax", "zFarMax", "unused"},
                 {0, 0, 1, Colormap::Gray},
                 kRoleHierarchy}};
  }
  std::string name() const override { return "minmax"; }
  std::string summary() const override {
    return "The N-buffer's bounds over quadtree-aligned cells of the light layers (a min-max "
           "mipmap), a smaller alternative to the N-buffer; trace.hierarchy chooses one of "
           "the two.";
  }
  std::string thesisSection() const override { return "thesis §5.1"; }

  void run(Frame& frame) override {
    const GlTexture& nearLayer = frame.input(*this, "near");
    const GlTexture& farLayer = frame.input(*this, "far");
    const int width = nearLayer.width(), height = nearLayer.height();
    const glm::ivec2 base = minmaxBaseSize(width, height);
    GlTexture& levels =
        frame.output(*this, "levels", base.x, base.y, 0, minmaxMipLevels(width, height));
    builder_.build(nearLayer, farLayer, levels);
    frame.counters["minmax.levels"] = minmaxTopLevel(width, height) + 1;
  }

private:
  MinMaxBuilder builder_;
};

}  // namespace

std::unique_ptr<Stage> makeMinMaxStage() { return std::make_unique<MinMaxStage>(); }
