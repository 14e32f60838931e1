// The registry: every stage, one line each, with the edges the pipeline cannot infer.
// A slot without an edge is wired to the one output of its name (app/core/pipeline.h); the
// pipeline derives the execution order from the edges and runs only what is asked for.
// Thesis Algorithm 1 (deferred form) reads top to bottom; then the other methods, the
// ground truth and the final image. A new shadow method is one more line here.
#include "core/pipeline.h"

// 1. Shared inputs: the light and the eye's G-buffer; the light's depth layers.
std::unique_ptr<Stage> makeLightStage();
std::unique_ptr<Stage> makeGBufferStage();
std::unique_ptr<Stage> makeHashStage();
std::unique_ptr<Stage> makeHashStatsStage();
std::unique_ptr<Stage> makeLightLayersStage();
std::unique_ptr<Stage> makeNBufferStage();
std::unique_ptr<Stage> makeMinMaxStage();
// 2. Monte Carlo soft shadows (Curtis & Olano).
std::unique_ptr<Stage> makeClassifyStage();
std::unique_ptr<Stage> makeTraceStage();
std::unique_ptr<Stage> makeFilterStage();
// 3. Baselines and the other methods.
std::unique_ptr<Stage> makeHardShadowStage();
std::unique_ptr<Stage> makePcssStage();
std::unique_ptr<Stage> makeSoftShadowMapStage();
// 4. 4D rasterization (Wang et al. 2020): a method, and a ground truth at its samples.
std::unique_ptr<Stage> makeRaster4dStage();
// 5. Ground truth and its comparison; 6. the image.
std::unique_ptr<Stage> makeReferenceStage();
std::unique_ptr<Stage> makeReceiversStage();
std::unique_ptr<Stage> makeErrorStage();
std::unique_ptr<Stage> makeCompositeStage();

namespace {
// Registered by tests (core/pipeline.h registerTestStage); a function-local static, so a
// registration at file scope in another translation unit finds it constructed.
struct TestStage {
  StageFactory make;
  std::vector<StageEntry::Edge> edges;
};
std::vector<TestStage>& testStages() {
  static std::vector<TestStage> stages;
  return stages;
}
}  // namespace

std::vector<StageEntry> makeRegistry() {
  std::vector<StageEntry> registry;
  auto add = [&](std::unique_ptr<Stage> stage, std::vector<StageEntry::Edge> edges = {}) {
    registry.push_back({std::move(stage), std::move(edges)});
  };
  add(makeLightStage());                             // §3, Eq 3.1-3.2
  add(makeGBufferStage());                           // Alg. 1, step 1
  add(makeHashStage());                              // §3.1, App. A
  add(makeHashStatsStage());                         // §3.1, §4.3, App. A (docs/hash_stats.md)
  add(makeLightLayersStage());                       // §3.3
  add(makeNBufferStage());                           // §3.5
  add(makeMinMaxStage());                            // §5.1, decisions/024
  add(makeClassifyStage());                          // §3.6, Eq 3.3
  add(makeTraceStage());                             // §3.1-3.7, Alg. 2
  add(makeFilterStage(), {{"visibility", "trace.visibility"}});  // §3, Fig 3.2
  add(makeHardShadowStage());                        // §2.3
  add(makePcssStage());                              // Fernando 2005
  add(makeSoftShadowMapStage());                     // Atty et al. 2006 §3
  add(makeRaster4dStage());                          // Wang et al. 2020, Alg. 1-3
  add(makeReferenceStage());                         // ground truth (Embree)
  add(makeReceiversStage());                         // Atty 2006 §4.2.1: receivers only
  add(makeErrorStage());                             // Atty 2006 §4.2.1
  add(makeCompositeStage());                         // Alg. 1, last step
  for (const TestStage& test : testStages()) add(test.make(), test.edges);  // none in the program
  return registry;
}

bool registerTestStage(StageFactory make, std::vector<StageEntry::Edge> edges) {
  testStages().push_back({make, std::move(edges)});
  return true;
}
