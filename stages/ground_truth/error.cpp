// Stage `error` (docs/design.md#ground-truth): a method's visibility minus the exact reference, as
// images (signed, with a diverging colormap; absolute) and as numbers in frame.counters (RMSE, max,
// mean |error| in shadow after Atty et al. 2006 §4.2.1, 99th percentile). Only receivers inside the
// light's map count: the background has no shadow and, outside the map, no method knows anything
// (classify marks both). `pixels = receivers` narrows that to the receiver-only objects (stage
// `receivers`): soft shadow maps compute no self-shadowing (Atty et al. 2006 §3), and §4.2.1
// measures on the receiver, so an occluder's own surface would count an error the paper never
// measures. Runs only while both inputs are written.
//
// On the CPU: the reference is a CPU image anyway, and the percentile and OIIO's compare
// need the values there; at 512x512 the read-back costs a few milliseconds.
#include <cmath>

#include "reference/error_metrics.h"
#include "core/frame.h"

namespace {

class ErrorStage final : public Stage {
public:
  ErrorStage() {
    inputs_ = {
        Input::choice("method", "The shadow method's visibility to measure.", kRoleShadowMethod,
                      "method", "filter", /*allowNone=*/false),
        Input::choice("truth", "The ground truth it is measured against.", kRoleGroundTruth,
                      "against", "reference", /*allowNone=*/false),
        Input::texture("mask", "Classes: background and receivers outside the light's map do "
                               "not count.", GL_R32F),
        Input::texture("flag", "1 where the pixel shows a receiver-only object (stage "
                               "receivers; pixels = receivers counts only those).", GL_R8),
    };
    outputs_ = {
        {"signed", "Method minus reference: > 0 too bright (missed occluders), < 0 too dark "
                   "(over-occlusion). 0 where the pixel does not count.",
         GL_R32F, {"error"}, {0, -1, 1, Colormap::Diverging, true}},
        {"absolute", "|method - reference| (0 where the pixel does not count).", GL_R32F,
         {"error"}, {0, 0, 1, Colormap::Perceptual, true}},
    };
    params_ = {
        Param::choice("method", "Which shadow method is measured (every stage whose output "
                                "is a shadow method's visibility).", {}, 0),
        Param::choice("against", "The ground truth (every stage whose output is one).", {}, 0),
        Param::choice("pixels", "Which receivers count. all: every surface inside the light's "
                                "map, occluders included. receivers: only the scene's "
                                "receiver_only objects, the paper's metric (Atty et al. 2006 "
                                "§4.2.1 measure on the receiver; soft shadow maps compute no "
                                "self-shadowing, §3, so an occluder's own shading is an error "
                                "they never measure).", {"all", "receivers"}, 0),
    };
  }
  std::string name() const override { return "error"; }
  std::string summary() const override {
    return "Difference between a method's visibility and the exact reference, with RMSE, max, "
           "mean error in shadow and p99.";
  }
  std::string thesisSection() const override { return "Atty et al. 2006 §4.2.1"; }

  void run(Frame& frame) override {
    if (!frame.connected(*this, "truth") || !frame.connected(*this, "method")) {
      frame.textures.erase("error.signed");  // nothing to compare (off, or still pending)
      frame.textures.erase("error.absolute");
      return;
    }
    const int w = frame.eyeWidth, h = frame.eyeHeight;
    const std::vector<float> method = frame.input(*this, "method").readFloats();
    const std::vector<float> reference = frame.input(*this, "truth").readFloats();
    const std::vector<float> mask = frame.input(*this, "mask").readFloats();
    const bool receiversOnly = param("pixels").asEnum() == "receivers";
    std::vector<float> receiver;
    if (receiversOnly) receiver = frame.input(*this, "flag").readFloats();
    const std::vector<std::uint8_t> counted = countedPixels(mask, receiversOnly ? &receiver : nullptr);
    std::vector<float> signedError;
    const ErrorMetrics metrics = computeErrorMetrics(method, reference, counted, w, h, &signedError);
    std::vector<float> absolute(signedError.size());
    for (size_t i = 0; i < signedError.size(); ++i) absolute[i] = std::fabs(signedError[i]);
    upload(frame.output(*this, "signed", w, h), signedError);
    upload(frame.output(*this, "absolute", w, h), absolute);

    frame.counters["error.rmse"] = metrics.rmse;
    frame.counters["error.max"] = metrics.max;
    frame.counters["error.meanAbsInShadow"] = metrics.meanAbsInShadow;
    frame.counters["error.p99"] = metrics.p99;
    frame.counters["error.meanSigned"] = metrics.meanSigned;
    frame.counters["error.pixels"] = double(metrics.pixels);
    frame.counters["error.pixelsInShadow"] = double(metrics.pixelsInShadow);
  }

private:
  static void upload(GlTexture& texture, const std::vector<float>& values) {
    glTextureSubImage2D(texture.id(), 0, 0, 0, texture.width(), texture.height(), GL_RED,
                        GL_FLOAT, values.data());
  }
};

}  // namespace

std::unique_ptr<Stage> makeErrorStage() { return std::make_unique<ErrorStage>(); }
