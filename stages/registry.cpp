// The pipeline, in execution order (thesis Algorithm 1, deferred form; DESIGN.md §2).
#include <memory>
#include <vector>

#include "core/stage.h"

std::unique_ptr<Stage> makeGBufferStage();
std::unique_ptr<Stage> makeHashStage();
std::unique_ptr<Stage> makeLightLayersStage();
std::unique_ptr<Stage> makeNBufferStage();
std::unique_ptr<Stage> makeClassifyStage();
std::unique_ptr<Stage> makeHardShadowStage();
std::unique_ptr<Stage> makeTraceStage();
std::unique_ptr<Stage> makeFilterStage();
std::unique_ptr<Stage> makeReferenceStage();
std::unique_ptr<Stage> makeErrorStage();
std::unique_ptr<Stage> makeCompositeStage();

std::vector<std::unique_ptr<Stage>> makeStages() {
  std::vector<std::unique_ptr<Stage>> stages;
  stages.push_back(makeGBufferStage());
  stages.push_back(makeHashStage());
  stages.push_back(makeLightLayersStage());
  stages.push_back(makeNBufferStage());
  stages.push_back(makeClassifyStage());
  stages.push_back(makeHardShadowStage());
  stages.push_back(makeTraceStage());
  stages.push_back(makeFilterStage());
  stages.push_back(makeReferenceStage());  // ground truth (off by default; DESIGN.md §7)
  stages.push_back(makeErrorStage());
  stages.push_back(makeCompositeStage());
  return stages;
}
