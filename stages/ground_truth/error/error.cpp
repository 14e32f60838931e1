// Stage `error` (docs/design.md#ground-truth): a method's visibility minus the exact reference, as
// images (signed, with a diverging colormap; absolute) and as numbers in frame.counters (RMSE, max,
// mean |error| in shadow after Atty et al. 2006 §4.2.1, 99th percentile). Only receivers inside the
// light's map count: the background has no shadow and, outside the map, no method knows anything
// (classify marks both). `pixels = receivers` narrows that to the receiver-only objects (stage
// `receivers`): soft shadow maps compute no self-shadowing (Atty et al. 2006 §3), and §4.2.1
// measures on the receiver, so an occluder's own surface would count an error the paper never
// measures. Runs only while both inputs are written.
//
// On the GPU (shaders/ground_truth/error/error.comp, error_histogram.comp, error_reduce.comp; layouts in
// stages/ground_truth/error/error_layout.h): one pixel per invocation, each 8 x 8 group's sums reduced in
// shared memory, then one group adds the groups' records; the 99th percentile is selected
// exactly (a radix select over the bits of |error|). The numbers are read after the frame
// (Frame::readAfterFrame), so the stage never waits for the GPU. The CPU's computeErrorMetrics
// (app/reference/error_metrics.h, a lesson crop's numbers) follows the same definitions.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#include "core/frame.h"
#include "gl/gpu_layout.h"
#include "gl/shader_program.h"

namespace gpu {
#include "ground_truth/error/error_layout.h"
}  // namespace gpu

static_assert(sizeof(gpu::ErrorSums) == 48 && offsetof(gpu::ErrorSums, sums) == 16 &&
              offsetof(gpu::ErrorSums, squares) == 32);
static_assert(sizeof(gpu::ErrorTotals) == 64 && offsetof(gpu::ErrorTotals, select) == 48);
static_assert(gpu::distinctBelow({ERROR_METHOD_UNIT, ERROR_TRUTH_UNIT, ERROR_MASK_UNIT,
                                  ERROR_FLAG_UNIT}, gpu::kTextureUnits));
static_assert(gpu::distinctBelow({ERROR_SIGNED_IMAGE, ERROR_ABSOLUTE_IMAGE}, gpu::kImageUnits));
static_assert(gpu::distinctBelow({ERROR_GROUP_SUMS_BINDING, ERROR_TOTALS_BINDING,
                                  ERROR_HISTOGRAM_BINDING}, gpu::kStorageBindings));
static_assert(gpu::distinctBelow({ERROR_RECEIVERS_ONLY_LOCATION, ERROR_RADIX_PASS_LOCATION,
                                  ERROR_REDUCE_MODE_LOCATION}, gpu::kUniformLocations));
static_assert(ERROR_RADIX_BINS == 1 << ERROR_RADIX_BITS &&
              ERROR_RADIX_BITS * ERROR_RADIX_PASSES == 32 &&
              ERROR_RADIX_BINS <= ERROR_REDUCE_GROUP);

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
    const bool receiversOnly = param("pixels").asEnum() == "receivers";
    const GlTexture& mask = frame.input(*this, "mask");
    glBindTextureUnit(ERROR_METHOD_UNIT, frame.input(*this, "method").id());
    glBindTextureUnit(ERROR_TRUTH_UNIT, frame.input(*this, "truth").id());
    glBindTextureUnit(ERROR_MASK_UNIT, mask.id());
    // The flag is read only for pixels = receivers; otherwise the unit holds the mask, so
    // that no sampler of the program refers to an empty unit.
    glBindTextureUnit(ERROR_FLAG_UNIT,
                      receiversOnly ? frame.input(*this, "flag").id() : mask.id());
    glBindImageTexture(ERROR_SIGNED_IMAGE, frame.output(*this, "signed", w, h).id(), 0, GL_FALSE,
                       0, GL_WRITE_ONLY, GL_R32F);
    glBindImageTexture(ERROR_ABSOLUTE_IMAGE, frame.output(*this, "absolute", w, h).id(), 0,
                       GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    const GLuint groupsX = GLuint((w + 7) / 8), groupsY = GLuint((h + 7) / 8);
    // The records' count is the buffer's length (error_reduce.comp reads groupSums.length()).
    const GLsizeiptr groupBytes = GLsizeiptr(groupsX) * groupsY * GLsizeiptr(sizeof(gpu::ErrorSums));
    if (groupBytes != groupBytes_) groupSums_.upload(nullptr, size_t(groupBytes)), groupBytes_ = groupBytes;
    if (!totalsAllocated_) {
      totals_.upload(nullptr, sizeof(gpu::ErrorTotals));
      histogram_.upload(nullptr, ERROR_RADIX_BINS * sizeof(std::uint32_t));
      totalsAllocated_ = true;
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, ERROR_GROUP_SUMS_BINDING, groupSums_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, ERROR_TOTALS_BINDING, totals_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, ERROR_HISTOGRAM_BINDING, histogram_.id());

    // The error per pixel, its images and each group's sums; then the totals.
    errorProgram_.use();
    glUniform1i(ERROR_RECEIVERS_ONLY_LOCATION, receiversOnly);
    glDispatchCompute(groupsX, groupsY, 1);
    glMemoryBarrier(kImageResults | kBufferResults);
    reduceProgram_.use();
    glUniform1i(ERROR_REDUCE_MODE_LOCATION, ERROR_REDUCE_SUMS);
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(kBufferResults);
    // The 99th percentile: a radix select, ERROR_RADIX_BITS bits of |error| per pass.
    const std::uint32_t zero = 0;
    for (int pass = 0; pass < ERROR_RADIX_PASSES; ++pass) {
      glClearNamedBufferData(histogram_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
      histogramProgram_.use();
      glUniform1i(ERROR_RECEIVERS_ONLY_LOCATION, receiversOnly);
      glUniform1i(ERROR_RADIX_PASS_LOCATION, pass);
      glDispatchCompute(groupsX, groupsY, 1);
      glMemoryBarrier(kBufferResults);
      reduceProgram_.use();
      glUniform1i(ERROR_REDUCE_MODE_LOCATION, ERROR_REDUCE_SELECT);
      glDispatchCompute(1, 1, 1);
      glMemoryBarrier(kBufferResults);
    }
    const double n = double(w) * double(h);
    frame.readAfterFrame(totals_, 0, sizeof(gpu::ErrorTotals),
                         [n](const std::vector<unsigned char>& bytes, Frame& frame) {
                           gpu::ErrorTotals totals{};
                           std::memcpy(&totals, bytes.data(), sizeof totals);
                           writeCounters(totals, n, frame.counters);
                         });
  }

private:
  static double doubleFromWords(std::uint32_t low, std::uint32_t high) {
    const std::uint64_t bits = (std::uint64_t(high) << 32) | low;
    double value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
  }
  static float floatFromBits(std::uint32_t bits) {
    float value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
  }
  // The statistics of app/reference/error_metrics.h from the GPU's sums over the `n` pixels
  // of the image: the RMSE over the counted pixels as the CPU computes it (OIIO's RMS over all
  // n, where the pixels that do not count differ by 0, rescaled by sqrt(n / pixels)).
  static void writeCounters(const gpu::ErrorTotals& totals, double n,
                            std::map<std::string, double>& counters) {
    const gpu::ErrorSums& sums = totals.sums;
    const double pixels = sums.counts.x, inShadow = sums.counts.y;
    double rmse = 0, max = 0, meanAbsInShadow = 0, p99 = 0, meanSigned = 0;
    if (pixels > 0) {
      const double squares = doubleFromWords(sums.squares.x, sums.squares.y);
      rmse = std::sqrt(squares / n) * std::sqrt(n / pixels);
      max = floatFromBits(sums.counts.z);
      meanSigned = doubleFromWords(sums.sums.x, sums.sums.y) / pixels;
      meanAbsInShadow = inShadow > 0 ? doubleFromWords(sums.sums.z, sums.sums.w) / inShadow : 0.0;
      if (totals.select.z != ERROR_RADIX_PASSES)
        throw std::logic_error("error: the percentile's select found no value (" +
                               std::to_string(totals.select.z) + " of " +
                               std::to_string(ERROR_RADIX_PASSES) + " passes)");
      p99 = floatFromBits(totals.select.x);
    }
    counters["error.rmse"] = rmse;
    counters["error.max"] = max;
    counters["error.meanAbsInShadow"] = meanAbsInShadow;
    counters["error.p99"] = p99;
    counters["error.meanSigned"] = meanSigned;
    counters["error.pixels"] = pixels;
    counters["error.pixelsInShadow"] = inShadow;
  }

  GlBuffer groupSums_, totals_, histogram_;
  GLsizeiptr groupBytes_ = -1;
  bool totalsAllocated_ = false;
  ShaderProgram errorProgram_{{{GL_COMPUTE_SHADER, "ground_truth/error/error.comp"}}};
  ShaderProgram histogramProgram_{{{GL_COMPUTE_SHADER, "ground_truth/error/error_histogram.comp"}}};
  ShaderProgram reduceProgram_{{{GL_COMPUTE_SHADER, "ground_truth/error/error_reduce.comp"}}};
};

}  // namespace

std::unique_ptr<Stage> makeErrorStage() { return std::make_unique<ErrorStage>(); }
