// What the window asks the stage graph (app/core/pipeline.h), never a stage's name: the
// image, the comparison with the ground truth, the light's depth layers, the stages a pick
// drives and the stage that records one pixel's rays are found by what the stages declare
// (roles, choice slots, outputs, capabilities: app/core/stage.h Capability), so a new stage
// shows up without edits here.
#pragma once
#include <string>
#include <vector>

class Pipeline;
struct Frame;
class Stage;

// The final image: the first output of the stage whose choice slot takes a shadow method's
// visibility and that is not itself measured ("composite.color"); "" if none.
std::string finalImageOutput(const Pipeline& pipeline);
// The comparison with the ground truth: the first output of the stage whose choice slot takes
// a ground truth ("error.signed"); "" if none.
std::string comparisonOutput(const Pipeline& pipeline);
// The ground truth the comparison is set against now (its choice parameter, "reference" or
// "raster4d"), nullptr if there is no comparison stage.
Stage* groundTruthStage(const Pipeline& pipeline);
// The comparison's choice parameter, "stage.key" ("error.against"), and the method it
// measures ("error.method"); "" if none.
std::string groundTruthChoiceKey(const Pipeline& pipeline);
std::string measuredMethodKey(const Pipeline& pipeline);
// A ground truth computed on the GPU inside the frame, so timed like a method: the first
// stage whose output is both a ground truth and a shadow method ("raster4d"); "" if none.
std::string gpuGroundTruth(const Pipeline& pipeline);
// The stages that declare `capability` (kCapabilityPicksEyePixel: raster4d, ssm), in order.
std::vector<Stage*> stagesThatCan(const Pipeline& pipeline, unsigned capability);
// The picked pixel's mask over the light's sample grid: the output pickedMask of the first
// stage with kCapabilityPickedLightMask ("raster4d.pickedMask"); "" if none.
std::string lightMaskOutput(const Pipeline& pipeline);
// The light's depth layers: the outputs "near" and "far" of the one stage that declares both
// ("light_layers.near", "light_layers.far"); empty strings if none does.
struct LayerOutputs {
  std::string near, far;
};
LayerOutputs layerOutputs(const Pipeline& pipeline);
bool hasLayerOutputs(const Stage& stage);
// The stage whose rays the trace panel shows: the first with kCapabilityRecordsRays (the
// trace: record_x, record_y in image coordinates, rays per side); nullptr if none.
Stage* recordingStage(const Pipeline& pipeline);
// The producer wired to `slot` of the recording stage ("nbuffer.levels" for "levels"); "" if
// there is no such stage or slot.
std::string recordingInput(const Pipeline& pipeline, const std::string& slot);
// Where the trace panel draws a ray's visited windows: the hierarchy the recording stage
// searched when it holds one map-sized layer per level (the N-buffer; `perLevel`: show the
// finest level visited); else the near layer, level 0, under the cells (a min-max mipmap's
// levels are smaller mip levels that the windows, in level-0 texels, do not fit). Empty output:
// nothing to show on.
struct RayOverlayTarget {
  std::string output;
  bool perLevel = false;
};
RayOverlayTarget rayOverlayTarget(const Pipeline& pipeline, const Frame* frame);
// What the trace panel needs run: the recording stage's texture outputs.
std::vector<std::string> traceOutputs(const Pipeline& pipeline);
