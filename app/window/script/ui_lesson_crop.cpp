#include "window/script/ui_lesson_crop.h"

#include "reference/error_metrics.h"
#include "window/ui_state.h"

using nlohmann::json;

namespace {

const char* const kNames[] = {"rmse",       "max",    "meanAbsInShadow", "p99",
                              "meanSigned", "pixels", "pixelsInShadow"};

double pick(const ErrorMetrics& m, const std::string& key) {
  if (key == "rmse") return m.rmse;
  if (key == "max") return m.max;
  if (key == "meanAbsInShadow") return m.meanAbsInShadow;
  if (key == "p99") return m.p99;
  if (key == "meanSigned") return m.meanSigned;
  if (key == "pixels") return double(m.pixels);
  return double(m.pixelsInShadow);
}

}  // namespace

// 1. The action's argument.
std::string checkCrop(const json& value) {
  if (value == "none") return "";
  bool ok = value.is_array() && value.size() == 4;
  for (size_t i = 0; ok && i < 4; ++i)
    ok = value[i].is_number_integer() && value[i].get<long long>() >= (i < 2 ? 0 : 1) &&
         value[i].get<long long>() <= 8192;
  return ok ? "" : "expected [x, y, width, height] in image pixels (row 0 at the top), or \"none\"";
}

ImageRect cropFromJson(const json& value) {
  if (value == "none") return {};
  return {value[0].get<int>(), value[1].get<int>(), value[2].get<int>(), value[3].get<int>()};
}

// 2. The error stage's numbers inside the crop.
bool isCropNumber(const std::string& name) {
  if (name.rfind("crop.", 0) != 0) return false;
  for (const char* key : kNames)
    if (name.substr(5) == key) return true;
  return false;
}

bool cropNumber(const UiState& state, const ImageRect& crop, const std::string& name,
                double& value, std::string& problem) {
  const Frame* frame = state.session.frame.get();
  if (crop.empty()) {
    problem = "{" + name + "}: no crop is set (add {\"crop\": [x, y, w, h]} before it)";
    return false;
  }
  const int w = frame ? frame->eyeWidth : 0, h = frame ? frame->eyeHeight : 0;
  if (crop.x + crop.width > w || crop.y + crop.height > h) {
    problem = "{" + name + "}: the crop reaches past the " + std::to_string(w) + "x" +
              std::to_string(h) + " eye image";
    return false;
  }
  for (const auto& stage : state.session.pipeline.stages()) {
    if (stage->name() != "error") continue;
    if (!frame->connected(*stage, "method") || !frame->connected(*stage, "truth") ||
        !frame->has("error.signed")) {
      problem = "{" + name + "}: the error stage compared nothing this frame (reference off?)";
      return false;
    }
    const std::vector<float> method = frame->input(*stage, "method").readFloats();
    const std::vector<float> truth = frame->input(*stage, "truth").readFloats();
    const std::vector<float> mask = frame->input(*stage, "mask").readFloats();
    std::vector<float> receiver;
    const bool receiversOnly = stage->param("pixels").asEnum() == "receivers";
    if (receiversOnly) receiver = frame->input(*stage, "flag").readFloats();
    // As the error stage counts, and only inside the crop (GL rows run bottom-up, the
    // crop's top-down).
    const std::vector<std::uint8_t> everywhere = countedPixels(mask, receiversOnly ? &receiver : nullptr);
    std::vector<std::uint8_t> counted(mask.size(), 0);
    for (int y = crop.y; y < crop.y + crop.height; ++y)
      for (int x = crop.x; x < crop.x + crop.width; ++x) {
        const size_t i = size_t(h - 1 - y) * size_t(w) + size_t(x);
        counted[i] = everywhere[i];
      }
    value = pick(computeErrorMetrics(method, truth, counted, w, h), name.substr(5));
    return true;
  }
  problem = "{" + name + "}: no error stage in this pipeline";
  return false;
}
