// The stage graph (app/core/pipeline.h): wiring checks, the derived order, demand-driven
// runs, the shadow-method role, and a contract over every registered stage's parameters.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "bench/bench_configs.h"
#include "bench/bench_measure.h"
#include "core/pipeline.h"
#include "scene/scene_builtin.h"
#include "scene/scene_stress.h"
#include "support/gl_test.h"

namespace {

// A stage with the given slots and outputs that writes nothing (graph structure only).
class FakeStage final : public Stage {
public:
  FakeStage(std::string name, std::vector<Input> inputs, std::vector<Output> outputs,
            std::vector<Param> params = {})
      : name_(std::move(name)) {
    inputs_ = std::move(inputs), outputs_ = std::move(outputs), params_ = std::move(params);
  }
  std::string name() const override { return name_; }
  std::string summary() const override { return "test stage"; }
  std::string thesisSection() const override { return ""; }
  void run(Frame&) override {}
  void declareCapabilities(unsigned capabilities) { capabilities_ = capabilities; }

private:
  std::string name_;
};

Output texture(const std::string& name, GLenum format = GL_R32F, unsigned roles = kRoleNone) {
  return {name, "test output", format, {"v"}, {}, roles};
}

StageEntry entry(std::string name, std::vector<Input> inputs, std::vector<Output> outputs,
                 std::vector<StageEntry::Edge> edges = {}, std::vector<Param> params = {}) {
  return {std::make_unique<FakeStage>(std::move(name), std::move(inputs), std::move(outputs),
                                      std::move(params)),
          std::move(edges)};
}

std::string buildError(std::vector<StageEntry> registry) {
  try {
    Pipeline pipeline(std::move(registry));
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

std::vector<std::string> stageNames(const Pipeline& pipeline) {
  std::vector<std::string> names;
  for (const auto& stage : pipeline.stages()) names.push_back(stage->name());
  return names;
}

}  // namespace

TEST(StageGraph, OrderIsDerivedFromTheEdgesNotTheRegistry) {
  std::vector<StageEntry> registry;
  registry.push_back(entry("consumer", {Input::texture("b", "", GL_R32F)}, {texture("c")}));
  registry.push_back(entry("middle", {Input::texture("a", "", GL_R32F)}, {texture("b")}));
  registry.push_back(entry("source", {}, {texture("a")}));
  Pipeline pipeline(std::move(registry));
  EXPECT_EQ(stageNames(pipeline), (std::vector<std::string>{"source", "middle", "consumer"}));
  EXPECT_EQ(pipeline.source("consumer", "b"), "middle.b");
  EXPECT_EQ(pipeline.dependencies({"consumer.c"}),
            (std::vector<std::string>{"source", "middle", "consumer"}));
  EXPECT_EQ(pipeline.dependencies({"middle.b"}), (std::vector<std::string>{"source", "middle"}));
}

TEST(StageGraph, BadGraphsAreRefusedNamingStageAndSlot) {
  {  // no producer
    std::vector<StageEntry> r;
    r.push_back(entry("lonely", {Input::texture("missing", "")}, {texture("x")}));
    const std::string error = buildError(std::move(r));
    EXPECT_NE(error.find("lonely"), std::string::npos) << error;
    EXPECT_NE(error.find("missing"), std::string::npos) << error;
  }
  {  // ambiguous producer
    std::vector<StageEntry> r;
    r.push_back(entry("one", {}, {texture("v")}));
    r.push_back(entry("two", {}, {texture("v")}));
    r.push_back(entry("reader", {Input::texture("v", "")}, {texture("out")}));
    const std::string error = buildError(std::move(r));
    EXPECT_NE(error.find("ambiguous"), std::string::npos) << error;
    EXPECT_NE(error.find("one.v"), std::string::npos) << error;
    EXPECT_NE(error.find("two.v"), std::string::npos) << error;
  }
  {  // format mismatch
    std::vector<StageEntry> r;
    r.push_back(entry("maker", {}, {texture("v", GL_RGBA32F)}));
    r.push_back(entry("reader", {Input::texture("v", "", GL_R32F)}, {texture("out")}));
    const std::string error = buildError(std::move(r));
    EXPECT_NE(error.find("format mismatch"), std::string::npos) << error;
    EXPECT_NE(error.find("reader"), std::string::npos) << error;
  }
  {  // buffer slot wired to a texture
    std::vector<StageEntry> r;
    r.push_back(entry("maker", {}, {texture("list")}));
    r.push_back(entry("reader", {Input::buffer("list", "")}, {texture("out")}));
    EXPECT_NE(buildError(std::move(r)).find("format mismatch"), std::string::npos);
  }
  {  // cycle
    std::vector<StageEntry> r;
    r.push_back(entry("a", {Input::texture("y", "")}, {texture("x")}));
    r.push_back(entry("b", {Input::texture("x", "")}, {texture("y")}));
    const std::string error = buildError(std::move(r));
    EXPECT_NE(error.find("cycle"), std::string::npos) << error;
    EXPECT_NE(error.find("a, b"), std::string::npos) << error;
  }
  {  // an edge naming a slot the stage does not have
    std::vector<StageEntry> r;
    r.push_back(entry("maker", {}, {texture("v")}));
    r.push_back(entry("reader", {Input::texture("v", "")}, {texture("out")}, {{"typo", "maker.v"}}));
    const std::string error = buildError(std::move(r));
    EXPECT_NE(error.find("no input slot 'typo'"), std::string::npos) << error;
  }
}

// A capability (app/core/stage.h) promises parameters and outputs; a stage that declares one
// without them is refused when the graph is built, naming the stage and what is missing.
TEST(StageGraph, ACapabilityIsRefusedWithoutWhatItPromises) {
  auto build = [](unsigned capabilities, std::vector<Param> params, std::vector<Output> outputs = {texture("v")},
                  std::vector<Input> inputs = {}) {
    auto stage = std::make_unique<FakeStage>("picker", std::move(inputs), std::move(outputs), std::move(params));
    stage->declareCapabilities(capabilities);
    std::vector<StageEntry> registry;
    registry.push_back({std::move(stage), {}});
    return buildError(std::move(registry));
  };
  const Param pickX = Param::integer("pick_x", "", -1, -1, 99), pickY = Param::integer("pick_y", "", -1, -1, 99);
  EXPECT_EQ(build(kCapabilityPicksEyePixel, {pickX, pickY}), "");
  std::string error = build(kCapabilityPicksEyePixel, {pickX});
  EXPECT_NE(error.find("'picker'"), std::string::npos) << error;
  EXPECT_NE(error.find("PicksEyePixel"), std::string::npos) << error;
  EXPECT_NE(error.find("'pick_y'"), std::string::npos) << error;
  error = build(kCapabilityPicksEyePixel, {pickX, Param::real("pick_y", "", 0, 0, 1)});
  EXPECT_NE(error.find("not an integer"), std::string::npos) << error;
  // The light mask needs its output and an eye pick to be the mask of.
  EXPECT_NE(build(kCapabilityPicksEyePixel | kCapabilityPickedLightMask, {pickX, pickY}).find("'pickedMask'"),
            std::string::npos);
  EXPECT_NE(build(kCapabilityPickedLightMask, {}, {texture("pickedMask")}).find("PicksEyePixel"),
            std::string::npos);
  EXPECT_EQ(build(kCapabilityPicksEyePixel | kCapabilityPickedLightMask, {pickX, pickY}, {texture("pickedMask")}), "");
  // Recording rays: record_x, record_y, rays and the near and far slots.
  const std::vector<Param> recording = {Param::integer("record_x", "", -1, -1, 99),
                                        Param::integer("record_y", "", -1, -1, 99),
                                        Param::integer("rays", "", 2, 1, 8)};
  EXPECT_NE(build(kCapabilityRecordsRays, recording).find("no input slot 'near'"), std::string::npos);
  EXPECT_NE(build(kCapabilityPicksMapTexel, {Param::integer("patch_x", "", -1, -1, 9),
                                             Param::integer("patch_y", "", -1, -1, 9)})
                .find("'resolution'"),
            std::string::npos);
  // The params alone declare nothing: no capability, nothing to check.
  EXPECT_EQ(build(kCapabilityNone, {pickX}), "");
}

// The registry's stages declare the capabilities the window drives them by.
TEST(StageGraph, TheRegistrysCapabilitiesAreWhereTheWindowNeedsThem) {
  Pipeline pipeline;
  std::vector<std::string> eyePick, mapPick, records, mask;
  for (const auto& stage : pipeline.stages()) {
    if (stage->can(kCapabilityPicksEyePixel)) eyePick.push_back(stage->name());
    if (stage->can(kCapabilityPicksMapTexel)) mapPick.push_back(stage->name());
    if (stage->can(kCapabilityRecordsRays)) records.push_back(stage->name());
    if (stage->can(kCapabilityPickedLightMask)) mask.push_back(stage->name());
  }
  EXPECT_EQ(eyePick, (std::vector<std::string>{"ssm", "raster4d"}));
  EXPECT_EQ(mapPick, (std::vector<std::string>{"ssm"}));
  EXPECT_EQ(records, (std::vector<std::string>{"trace"}));
  EXPECT_EQ(mask, (std::vector<std::string>{"raster4d"}));
}

TEST(StageGraph, ChoiceSlotsListEveryMethodAndFollowTheirParameter) {
  std::vector<StageEntry> r;
  r.push_back(entry("alpha", {}, {texture("visibility", GL_R32F, kRoleShadowMethod)}));
  r.push_back(entry("beta", {}, {texture("visibility", GL_R32F, kRoleShadowMethod)}));
  r.push_back(entry("unrelated", {}, {texture("other")}));
  r.push_back(entry("viewer",
                    {Input::choice("visibility", "", kRoleShadowMethod, "shadow", "beta", true)},
                    {texture("image")}, {}, {Param::choice("shadow", "which", {}, 0)}));
  Pipeline pipeline(std::move(r));
  const Param& shadow = pipeline.param("viewer.shadow");
  EXPECT_EQ(shadow.options, (std::vector<std::string>{"alpha", "beta", "none"}));
  EXPECT_EQ(shadow.asEnum(), "beta");  // the declared default
  EXPECT_EQ(pipeline.source("viewer", "visibility"), "beta.visibility");
  EXPECT_EQ(pipeline.dependencies({"viewer.image"}), (std::vector<std::string>{"beta", "viewer"}));
  ASSERT_EQ(pipeline.set("viewer.shadow=alpha"), "");
  EXPECT_EQ(pipeline.dependencies({"viewer.image"}), (std::vector<std::string>{"alpha", "viewer"}));
  ASSERT_EQ(pipeline.set("viewer.shadow=none"), "");
  EXPECT_EQ(pipeline.source("viewer", "visibility"), "");
  EXPECT_EQ(pipeline.dependencies({"viewer.image"}), (std::vector<std::string>{"viewer"}));
  EXPECT_NE(pipeline.set("viewer.shadow=unrelated"), "");  // not a method
}

// A choice slot may follow another stage's choice ("stage.key"): one parameter switches
// both; the candidates must be the same.
TEST(StageGraph, AChoiceSlotCanFollowAnotherStagesChoice) {
  auto registry = [](bool mismatch) {
    std::vector<StageEntry> r;
    r.push_back(entry("alpha", {}, {texture("levels", GL_RGBA32F, kRoleHierarchy)}));
    r.push_back(entry("beta", {}, {texture("levels", GL_RGBA32F, kRoleHierarchy)}));
    Input follower = Input::choice("levels", "", kRoleHierarchy, "chooser.which", "alpha", mismatch);
    follower.format = GL_RGBA32F;
    r.push_back(entry("follower", {follower}, {texture("bounds")}));
    Input chosen = Input::choice("levels", "", kRoleHierarchy, "which", "alpha", false);
    chosen.format = GL_RGBA32F;
    r.push_back(entry("chooser", {chosen, Input::texture("bounds", "")}, {texture("image")}, {},
                      {Param::choice("which", "which", {}, 0)}));
    return r;
  };
  Pipeline pipeline(registry(false));
  EXPECT_EQ(pipeline.source("follower", "levels"), "alpha.levels");
  EXPECT_EQ(pipeline.dependencies({"chooser.image"}),
            (std::vector<std::string>{"alpha", "follower", "chooser"}));
  ASSERT_EQ(pipeline.set("chooser.which=beta"), "");
  EXPECT_EQ(pipeline.source("follower", "levels"), "beta.levels");
  EXPECT_EQ(pipeline.dependencies({"chooser.image"}),
            (std::vector<std::string>{"beta", "follower", "chooser"}));
  // "none" among the follower's candidates but not the chooser's options: rejected.
  const std::string error = buildError(registry(true));
  EXPECT_NE(error.find("'chooser.which', which it follows"), std::string::npos) << error;
}

TEST(StageGraph, RevisionChangesWithEveryParameter) {
  Pipeline pipeline;
  const auto before = pipeline.revision();
  ASSERT_EQ(pipeline.set("trace.rays=3"), "");
  const auto changed = pipeline.revision();
  EXPECT_NE(changed, before);
  // trace.rays starts at auto (nominal value 2): a fixed 2 is another setting (the window
  // must rerun when its "auto" box is ticked), auto again is the same one.
  ASSERT_EQ(pipeline.set("trace.rays=2"), "");
  EXPECT_NE(pipeline.revision(), before);
  ASSERT_EQ(pipeline.set("trace.rays=auto"), "");
  EXPECT_EQ(pipeline.revision(), before);  // a fingerprint: back to the same values
}

// Between bench configurations every parameter returns to its value *and* its auto flag: a
// configuration that fixes light.resolution must not leave the next one at a fixed map.
TEST(StageGraph, ASnapshotRestoresAutoAsWellAsValues) {
  Pipeline pipeline;
  ASSERT_TRUE(pipeline.param("light.resolution").automatic);
  const ParamSnapshot defaults(pipeline);
  ASSERT_EQ(applySets(pipeline, {"light.resolution=1024", "trace.rays=3"}), "");
  defaults.restore();
  EXPECT_TRUE(pipeline.param("light.resolution").automatic);
  EXPECT_TRUE(pipeline.param("trace.rays").automatic);
  EXPECT_EQ(pipeline.revision(), Pipeline().revision());
}

TEST(StageGraph, TheRegistryIsAValidGraphAndAlgorithmOneRunsInOrder) {
  Pipeline pipeline;
  const std::vector<std::string> names = stageNames(pipeline);
  auto at = [&](const std::string& name) {
    return std::find(names.begin(), names.end(), name) - names.begin();
  };
  EXPECT_LT(at("light"), at("light_layers"));
  EXPECT_LT(at("light_layers"), at("nbuffer"));
  EXPECT_LT(at("nbuffer"), at("classify"));
  EXPECT_LT(at("classify"), at("trace"));
  EXPECT_LT(at("trace"), at("filter"));
  EXPECT_LT(at("filter"), at("composite"));
  // The methods are whatever the stages declare (no list to edit when one is added): the
  // stages, in execution order, with an output carrying the role, each an R32F visibility.
  for (const unsigned role : {unsigned(kRoleShadowMethod), unsigned(kRoleGroundTruth)}) {
    std::vector<std::string> declared;
    for (const auto& stage : pipeline.stages())
      for (const Output& output : stage->outputs())
        if (output.roles & role) {
          declared.push_back(stage->name());
          EXPECT_EQ(output.format, GLenum(GL_R32F)) << stage->name() << "." << output.name;
          EXPECT_EQ(pipeline.methodOutput(stage->name()), stage->name() + "." + output.name);
          break;
        }
    EXPECT_EQ(pipeline.methods(role), declared) << "role " << role;
  }
  // Among them the thesis's unfiltered and filtered rays, in Algorithm 1's order, and the
  // Embree reference as a ground truth.
  const std::vector<std::string> methods = pipeline.methods();
  const auto trace = std::find(methods.begin(), methods.end(), "trace");
  EXPECT_LT(trace, std::find(methods.begin(), methods.end(), "filter"));
  EXPECT_NE(trace, methods.end());
  const std::vector<std::string> truths = pipeline.methods(kRoleGroundTruth);
  EXPECT_NE(std::find(truths.begin(), truths.end(), "reference"), truths.end());
  const std::string dot = pipeline.dot();
  EXPECT_NE(dot.find("\"trace\" -> \"filter\" [label=\"visibility\"]"), std::string::npos) << dot;
}

// Demand-driven runs: only the dependency closure of what is asked for runs.
TEST(StageGraph, OnlyWhatTheRequestedOutputsNeedRuns) {
  PipelineRun run(makeBuiltinScene("cube"), {"light.resolution=128", "trace.hierarchy=nbuffer"},
                  64, 48);
  auto ran = [&] {
    std::set<std::string> names;
    for (const StageTime& time : run.pipeline->lastTimes())
      if (time.ran) names.insert(time.stage);
    return names;
  };
  run.pipeline->run(*run.frame, {"gbuffer.albedo"});
  EXPECT_EQ(ran(), (std::set<std::string>{"gbuffer"}));
  EXPECT_FALSE(run.frame->has("trace.visibility"));  // a stage that did not run leaves nothing

  run.pipeline->run(*run.frame, {"filter.visibility"});
  EXPECT_EQ(ran(), (std::set<std::string>{"light", "gbuffer", "light_layers", "nbuffer",
                                          "classify", "trace", "filter"}));
  const auto closure = run.pipeline->dependencies({"filter.visibility"});
  EXPECT_EQ(std::set<std::string>(closure.begin(), closure.end()), ran());

  // Over the min-max mipmap classification follows the trace's choice, so the N-buffer is not
  // built at all (docs/decisions/026-classify-follows-trace-hierarchy.md).
  ASSERT_EQ(run.pipeline->set("trace.hierarchy=minmax"), "");
  run.pipeline->run(*run.frame, {"filter.visibility"});
  EXPECT_EQ(ran(), (std::set<std::string>{"light", "gbuffer", "light_layers", "minmax",
                                          "classify", "trace", "filter"}));
  EXPECT_EQ(run.pipeline->source("classify", "levels"), "minmax.levels");
  ASSERT_EQ(run.pipeline->set("trace.hierarchy=nbuffer"), "");

  run.pipeline->run(*run.frame, {"hard_shadow.visibility"});
  EXPECT_EQ(ran(), (std::set<std::string>{"light", "gbuffer", "light_layers", "hard_shadow"}));
  EXPECT_EQ(run.pipeline->lastTime("trace").ran, false);
}

// `auto` hierarchy (docs/decisions/027-auto-hierarchy-rule.md): decided after the light stage from
// the map size and the eye's pixels, and what runs follows the decision; the parameter stays auto
// and shows the choice.
TEST(StageGraph, TheAutoHierarchyIsDecidedFromTheMapAndTheEye) {
  auto ran = [](const Pipeline& pipeline) {
    std::set<std::string> names;
    for (const StageTime& time : pipeline.lastTimes())
      if (time.ran) names.insert(time.stage);
    return names;
  };
  // Map 512 (10 levels: 2.6 M texel-levels) over 64 x 48 eye pixels: 853 per pixel > 12.
  PipelineRun small(makeBuiltinScene("cube"), {"light.resolution=512"}, 64, 48);
  ASSERT_TRUE(small.pipeline->param("trace.hierarchy").automatic);
  const auto revision = small.pipeline->revision();
  small.pipeline->run(*small.frame, {"filter.visibility"});
  EXPECT_EQ(ran(*small.pipeline), (std::set<std::string>{"light", "gbuffer", "light_layers",
                                                         "minmax", "classify", "trace", "filter"}));
  EXPECT_TRUE(small.pipeline->param("trace.hierarchy").automatic);
  EXPECT_EQ(small.pipeline->param("trace.hierarchy").asEnum(), "minmax");
  EXPECT_EQ(small.pipeline->revision(), revision);  // a decision is not a change of settings
  const auto& reasons = small.frame->autoReasons;
  EXPECT_TRUE(std::any_of(reasons.begin(), reasons.end(), [](const std::string& reason) {
    return reason.rfind("hierarchy minmax", 0) == 0;
  }));
  // The same map over 512 x 512 pixels: 10 per pixel, the N-buffer.
  PipelineRun large(makeBuiltinScene("cube"), {"light.resolution=512"}, 512, 512);
  large.pipeline->run(*large.frame, {"filter.visibility"});
  EXPECT_TRUE(large.pipeline->lastTime("nbuffer").ran);
  EXPECT_FALSE(large.pipeline->lastTime("minmax").ran);
  EXPECT_EQ(large.pipeline->source("classify", "levels"), "nbuffer.levels");
  // The same pipeline, the eye grown to 512 x 512: decided again, the other way (a stale
  // decision would keep the min-max mipmap).
  small.frame->eyeWidth = small.frame->eyeHeight = 512;
  small.pipeline->run(*small.frame, {"filter.visibility"});
  EXPECT_EQ(small.pipeline->param("trace.hierarchy").asEnum(), "nbuffer");
  EXPECT_TRUE(small.pipeline->lastTime("nbuffer").ran);
  EXPECT_FALSE(small.pipeline->lastTime("minmax").ran);
  EXPECT_FALSE(small.frame->has("minmax.levels"));
  small.frame->eyeWidth = 64;
  small.frame->eyeHeight = 48;
  // A hand-set hierarchy overrides the rule.
  ASSERT_EQ(small.pipeline->set("trace.hierarchy=nbuffer"), "");
  small.pipeline->run(*small.frame, {"filter.visibility"});
  EXPECT_TRUE(small.pipeline->lastTime("nbuffer").ran);
  EXPECT_FALSE(small.pipeline->lastTime("minmax").ran);
}

namespace {
// A stage whose `auto` choice picks `*pick` (set by the test).
class AutoChooser final : public Stage {
public:
  AutoChooser(const std::string* pick, std::string decidedAfter) : pick_(pick) {
    Input levels = Input::choice("levels", "", kRoleHierarchy, "which", "beta", false);
    levels.format = GL_RGBA32F;
    levels.decidedAfter = std::move(decidedAfter);
    inputs_ = {levels, Input::texture("d", "")};
    outputs_ = {texture("image")};
    params_ = {Param::choiceOrAuto("which", "which", {}, 0)};
  }
  std::string name() const override { return "chooser"; }
  std::string summary() const override { return "test stage"; }
  std::string thesisSection() const override { return ""; }
  void run(Frame&) override {}
  AutoChoice chooseAuto(const std::string&, const Frame&) const override { return {*pick_, "test"}; }

private:
  const std::string* pick_;
};

std::vector<StageEntry> autoChoiceRegistry(const std::string* pick, const std::string& after) {
  std::vector<StageEntry> r;
  r.push_back(entry("early", {}, {texture("x")}));  // only alpha needs it; ordered first
  r.push_back(entry("decider", {}, {texture("d")}));
  r.push_back(entry("alpha", {Input::texture("x", ""), Input::texture("d", "")},
                    {texture("levels", GL_RGBA32F, kRoleHierarchy)}));
  r.push_back(entry("beta", {Input::texture("d", "")}, {texture("levels", GL_RGBA32F, kRoleHierarchy)}));
  r.push_back(entry("unrelated", {}, {texture("u")}));
  r.push_back({std::make_unique<AutoChooser>(pick, after), {}});
  return r;
}
}  // namespace

// The decision comes mid-run: a stage skipped before it (`early`, needed only by the option
// chosen) runs once the decision needs it; a rule decided after a stage the chooser does not
// depend on is refused when the graph is built.
TEST(StageGraph, AnAutoChoiceMidRunRunsWhatItNeedsAndOnlyThat) {
  std::string pick = "alpha";
  Pipeline pipeline(autoChoiceRegistry(&pick, "decider"));
  EXPECT_EQ(stageNames(pipeline).front(), "early");
  EXPECT_EQ(pipeline.param("chooser.which").asEnum(), "beta");  // the declared default
  headlessContext();
  const Scene scene = makeBuiltinScene("plate");
  GpuScene gpuScene(scene);
  Frame frame(scene, gpuScene, pipeline);
  pipeline.run(frame, {"chooser.image"});
  EXPECT_EQ(pipeline.param("chooser.which").asEnum(), "alpha");
  EXPECT_TRUE(pipeline.lastTime("early").ran);
  EXPECT_TRUE(pipeline.lastTime("alpha").ran);
  EXPECT_FALSE(pipeline.lastTime("beta").ran);
  pick = "beta";
  pipeline.run(frame, {"chooser.image"});
  EXPECT_FALSE(pipeline.lastTime("early").ran);
  EXPECT_FALSE(pipeline.lastTime("alpha").ran);
  EXPECT_TRUE(pipeline.lastTime("beta").ran);
  pick = "gamma";  // not an option: an internal error, not a silent default
  EXPECT_THROW(pipeline.run(frame, {"chooser.image"}), std::logic_error);

  const std::string error = buildError(autoChoiceRegistry(&pick, "unrelated"));
  EXPECT_NE(error.find("decided after 'unrelated', which the slot's stage does not depend on"),
            std::string::npos) << error;
  EXPECT_NE(buildError(autoChoiceRegistry(&pick, "")).find("names no stage"), std::string::npos);
}

// Timings: a median over runs with identical settings; any change starts a new series.
TEST(StageGraph, TimingSeriesRestartWhenAParameterChanges) {
  PipelineRun run(makeBuiltinScene("cube"), {"light.resolution=128"}, 48, 48);
  run.run();
  run.run();
  EXPECT_EQ(run.pipeline->lastTime("trace").runs, 3);  // the constructor ran once
  EXPECT_GT(run.pipeline->lastTime("trace").median, 0.0);
  ASSERT_EQ(run.pipeline->set("filter.radius=2"), "");
  run.run();
  EXPECT_EQ(run.pipeline->lastTime("trace").runs, 1);
}

// The contract: every registered stage, every parameter at its minimum, its maximum and
// every option, on `cube` and a stress scene: the graph runs, every output is finite and every
// shadow method's visibility lies in [0, 1].
namespace {
void checkOutputs(PipelineRun& run, const std::string& what) {
  for (const auto& stage : run.pipeline->stages())
    for (const Output& output : stage->outputs()) {
      const std::string key = stage->name() + "." + output.name;
      if (output.isBuffer() || !run.frame->has(key)) continue;
      const GlTexture& texture = run.frame->texture(key);
      for (int layer = 0; layer < std::max(1, texture.layers()); ++layer) {
        const std::vector<float> values = texture.readFloats(layer);
        const bool visibility = (output.roles & (kRoleShadowMethod | kRoleGroundTruth)) != 0;
        size_t bad = 0;
        for (float v : values)
          if (!std::isfinite(v) || (visibility && (v < 0.0f || v > 1.0f))) ++bad;
        ASSERT_EQ(bad, 0u) << key << " layer " << layer << " with " << what;
      }
    }
}
}  // namespace

TEST(StageGraph, ContractEveryParameterAtItsLimitsKeepsOutputsFinite) {
  for (const std::string sceneName : {"cube", "stress_grazing"}) {
    const Scene scene = sceneName == "cube" ? makeBuiltinScene("cube") : makeStressScene(sceneName);
    // Small sizes keep the sweep short; parameters that set sizes are capped below.
    PipelineRun run(scene, {"light.resolution=128", "hash_stats.count_log2=12"}, 40, 32);
    const std::vector<std::string> keys = run.pipeline->paramKeys();
    for (const std::string& key : keys) {
      Param& param = run.pipeline->param(key);
      const Param saved = param;
      std::vector<double> values;
      if (param.type == Param::Type::Enum) {
        for (size_t i = 0; i < param.options.size(); ++i) values.push_back(double(i));
      } else {
        values = {param.min, param.max};
      }
      for (double value : values) {
        // Sizes and sample counts at their maximum would only cost time here: cap them.
        if (key == "light.resolution" && value > 256) value = 256;
        if (key == "reference.samples" && value > 4) value = 4;
        if (key == "hash_stats.count_log2" && value > 12) value = 12;
        if (key == "hash_stats.keys" && value > 2) value = 2;
        if (key == "reference.background" || key == "reference.cache") continue;
        param.value = value;
        if (key.rfind("reference.", 0) == 0 || key.rfind("error.", 0) == 0) {
          run.pipeline->param("reference.enabled").value = 1;
          run.pipeline->param("reference.cache").value = 0;
          run.pipeline->param("reference.samples").value = std::min(
              run.pipeline->param("reference.samples").value, 4.0);
        }
        run.run();
        checkOutputs(run, sceneName + ": " + key + "=" + param.toString());
        run.pipeline->param("reference.enabled").value = 0;
      }
      param = saved;
    }
  }
}

// A new shadow method is one stage and one registry line: this test-only method (half the
// light everywhere) appears in composite's and error's method lists with no other edit.
