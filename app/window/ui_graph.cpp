#include "window/ui_graph.h"

#include "core/frame.h"
#include "core/pipeline.h"

namespace {

bool hasOutput(const Stage& stage, const std::string& name) {
  for (const Output& output : stage.outputs())
    if (output.name == name) return true;
  return false;
}

// The first stage with a choice slot over `role` (composite: shadow methods; error: ground
// truths), skipping stages that choose `skipRole` too.
const Stage* chooser(const Pipeline& pipeline, unsigned role, unsigned skipRole) {
  for (const auto& stage : pipeline.stages()) {
    bool chooses = false, skipped = false;
    for (const Input& input : stage->inputs()) {
      chooses |= input.isChoice() && input.chooseRole == role;
      skipped |= input.isChoice() && input.chooseRole == skipRole;
    }
    if (chooses && !skipped && !stage->outputs().empty()) return stage.get();
  }
  return nullptr;
}

std::string firstOutput(const Stage* stage) {
  return stage ? stage->name() + "." + stage->outputs().front().name : "";
}

}  // namespace

std::string finalImageOutput(const Pipeline& pipeline) {
  return firstOutput(chooser(pipeline, kRoleShadowMethod, kRoleGroundTruth));
}

std::string comparisonOutput(const Pipeline& pipeline) {
  return firstOutput(chooser(pipeline, kRoleGroundTruth, kRoleNone));
}

namespace {

// "stage.key" of the comparison stage's choice slot over `role`.
std::string comparisonChoice(const Pipeline& pipeline, unsigned role) {
  const Stage* comparison = chooser(pipeline, kRoleGroundTruth, kRoleNone);
  if (!comparison) return "";
  for (const Input& input : comparison->inputs())
    if (input.isChoice() && input.chooseRole == role)
      return comparison->name() + "." + input.choiceParam;
  return "";
}

}  // namespace

std::string groundTruthChoiceKey(const Pipeline& pipeline) {
  return comparisonChoice(pipeline, kRoleGroundTruth);
}

std::string measuredMethodKey(const Pipeline& pipeline) {
  return comparisonChoice(pipeline, kRoleShadowMethod);
}

Stage* groundTruthStage(const Pipeline& pipeline) {
  const std::string key = groundTruthChoiceKey(pipeline);
  if (key.empty()) return nullptr;
  const std::string& chosen = pipeline.param(key).asEnum();
  return chosen == "none" ? nullptr : &pipeline.stage(chosen);
}

std::string gpuGroundTruth(const Pipeline& pipeline) {
  for (const auto& stage : pipeline.stages())
    for (const Output& output : stage->outputs())
      if ((output.roles & kRoleGroundTruth) && (output.roles & kRoleShadowMethod))
        return stage->name();
  return "";
}

std::vector<Stage*> stagesThatCan(const Pipeline& pipeline, unsigned capability) {
  std::vector<Stage*> found;
  for (const auto& stage : pipeline.stages())
    if ((stage->capabilities() & capability) == capability) found.push_back(stage.get());
  return found;
}

std::string lightMaskOutput(const Pipeline& pipeline) {
  const std::vector<Stage*> stages = stagesThatCan(pipeline, kCapabilityPickedLightMask);
  return stages.empty() ? "" : stages.front()->name() + "." + kPickedLightMaskOutput;
}

bool hasLayerOutputs(const Stage& stage) {
  return hasOutput(stage, "near") && hasOutput(stage, "far");
}

LayerOutputs layerOutputs(const Pipeline& pipeline) {
  for (const auto& stage : pipeline.stages())
    if (hasLayerOutputs(*stage)) return {stage->name() + ".near", stage->name() + ".far"};
  return {};
}

Stage* recordingStage(const Pipeline& pipeline) {
  const std::vector<Stage*> stages = stagesThatCan(pipeline, kCapabilityRecordsRays);
  return stages.empty() ? nullptr : stages.front();
}

std::string recordingInput(const Pipeline& pipeline, const std::string& slot) {
  const Stage* recorder = recordingStage(pipeline);
  if (!recorder) return "";
  for (const Input& input : recorder->inputs())
    if (input.name == slot) return pipeline.source(recorder->name(), slot);
  return "";
}

RayOverlayTarget rayOverlayTarget(const Pipeline& pipeline, const Frame* frame) {
  const std::string levels = recordingInput(pipeline, "levels");
  if (levels.empty()) return {};
  if (frame && frame->has(levels) && frame->texture(levels).isArray()) return {levels, true};
  return {recordingInput(pipeline, "near"), false};
}

std::vector<std::string> traceOutputs(const Pipeline& pipeline) {
  const Stage* recorder = recordingStage(pipeline);
  if (!recorder) return {};
  std::vector<std::string> outputs;
  for (const Output& output : recorder->outputs())
    if (!output.isBuffer()) outputs.push_back(recorder->name() + "." + output.name);
  return outputs;
}
