#include "window/ui_live_truth.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "window/ui_graph.h"

double estimateRaster4dMs(long long eyePixels, int samplesPerSide, long long occluderTriangles) {
  constexpr double kMs = 93, kPixels = 128 * 128, kSamples = 32, kTriangles = 12, kPower = 0.55;
  return kMs * (double(eyePixels) / kPixels) * (samplesPerSide / kSamples) *
         std::pow(double(std::max(occluderTriangles, 1LL)) / kTriangles, kPower);
}

namespace {

long long occluderTriangles(const Scene& scene) {
  long long triangles = 0;
  for (const SceneObject& object : scene.objects)
    if (!object.receiverOnly) triangles += (long long)object.mesh.triangleCount();
  return triangles;
}

int samplesOf(const Pipeline& pipeline, const std::string& stage) {
  for (const Param& param : pipeline.stage(stage).params())
    if (param.key == "samples") return param.asInt();
  return 32;
}

// The eye of the next run (the frame still holds the last run's size).
long long nextEyePixels(const Session& session) {
  const glm::ivec2 eye = session.currentKey({}).eye;
  return (long long)eye.x * eye.y;
}

long long eyePixels(const Session& session) {
  return session.frame ? (long long)session.frame->eyeWidth * session.frame->eyeHeight : 0;
}

// 1. The prediction: the last measured run on this scene scaled to this eye size and m (the
//    paper's Table 4: linear in rows), else the estimate.
void predict(LiveTruth& truth, const Session& session, const std::string& fast) {
  const int m = samplesOf(session.pipeline, fast);
  truth.fromMeasurement = truth.measuredScene == session.sceneLoads && truth.measuredPixels > 0;
  truth.predictedMs =
      truth.fromMeasurement
          ? truth.measuredMs * double(nextEyePixels(session)) / double(truth.measuredPixels) *
                double(m) / double(truth.measuredSamples)
          : estimateRaster4dMs(nextEyePixels(session), m, occluderTriangles(session.scene));
}

std::string currentTruth(const Pipeline& pipeline) {
  const std::string key = groundTruthChoiceKey(pipeline);
  return key.empty() ? "" : pipeline.param(key).asEnum();
}

}  // namespace

// 2. The rule, while automatic. The slow truth is the comparison's declared default (Embree).
std::string applyLiveTruthRule(LiveTruth& truth, Session& session) {
  Pipeline& pipeline = session.pipeline;
  const std::string key = groundTruthChoiceKey(pipeline), fast = gpuGroundTruth(pipeline);
  if (!truth.automatic || key.empty() || fast.empty()) return "";
  predict(truth, session, fast);
  const std::string methodKey = measuredMethodKey(pipeline);
  const bool measuringFast = !methodKey.empty() && pipeline.param(methodKey).asEnum() == fast;
  std::string slow;
  for (const auto& stage : pipeline.stages())
    for (const Input& input : stage->inputs())
      if (input.isChoice() && stage->name() + "." + input.choiceParam == key)
        slow = input.defaultChoice;
  const bool interactive = truth.predictedMs <= kInteractiveTruthMs;
  const std::string chosen = interactive && !measuringFast ? fast : slow;
  char reason[200];
  if (measuringFast)
    std::snprintf(reason, sizeof reason, "automatic: %s is the method measured", fast.c_str());
  else
    std::snprintf(reason, sizeof reason, "automatic: %s predicted %.0f ms %s %.0f ms, %s",
                  fast.c_str(), truth.predictedMs, interactive ? "<=" : ">", kInteractiveTruthMs,
                  truth.fromMeasurement ? "measured" : "estimated");
  truth.reason = reason;
  const bool changed = chosen != truth.chosen || currentTruth(pipeline) != chosen;
  pipeline.param(key).set(chosen);
  if (changed) pipeline.param(chosen + ".enabled").set("true");  // later, the user's to turn off
  truth.chosen = chosen;
  truth.seen = chosen;
  return changed ? chosen : "";
}

void keepUserTruth(LiveTruth& truth) {
  truth.automatic = false;
  truth.reason = "your choice; automatic off";
}

// 3. Each frame, before the run: a change of the choice that the rule did not make is the
//    user's; the rule follows the scene, the eye size and the measurements while the
//    comparison is shown.
void updateLiveTruth(LiveTruth& truth, Session& session, const std::vector<std::string>& shown,
                     std::string& status) {
  const std::string now = currentTruth(session.pipeline);
  if (now.empty()) return;
  if (truth.automatic && !truth.seen.empty() && now != truth.seen) keepUserTruth(truth);
  truth.seen = now;
  const std::string comparison = comparisonOutput(session.pipeline);
  if (!truth.automatic || std::find(shown.begin(), shown.end(), comparison) == shown.end()) return;
  if (!applyLiveTruthRule(truth, session).empty())
    status = "live error " + liveTruthLine(truth, session.pipeline);
}

// 4. After each run: raster4d's own time (not at preview resolution: it would scale badly).
void recordLiveTruthRun(LiveTruth& truth, const Session& session) {
  const std::string fast = gpuGroundTruth(session.pipeline);
  if (fast.empty() || session.previewing) return;
  const StageTime& time = session.pipeline.lastTime(fast);
  if (!time.ran || time.milliseconds <= 0) return;
  truth.measuredMs = time.milliseconds;
  truth.measuredPixels = eyePixels(session);
  truth.measuredSamples = samplesOf(session.pipeline, fast);
  truth.measuredScene = session.sceneLoads;
}

std::string liveTruthLine(const LiveTruth& truth, const Pipeline& pipeline) {
  const std::string now = currentTruth(pipeline);
  if (now.empty()) return "";
  const std::string& reason = truth.reason;
  return "against " + now + (reason.empty() ? "" : " (" + reason + ")");
}
