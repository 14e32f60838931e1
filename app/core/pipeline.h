// The stage graph (docs/design.md#stage-graph): the registry's stages, their slots wired to
// producers, checked and ordered when built; parameters addressed as "stage.key";
// demand-driven runs; per-stage timing.
#pragma once
#include <cstdint>
#include <map>
#include <set>
#include <memory>
#include <string>
#include <vector>

#include "core/frame.h"
#include "core/stage.h"

// One registry line: a stage and the edges that wire its input slots. A slot without an
// edge is wired to the one output of the same name elsewhere in the graph (gbuffer's
// "wsPosition", light's "light", ...); an edge names the producer where that is ambiguous.
struct StageEntry {
  struct Edge {
    std::string slot;    // "visibility"
    std::string source;  // "trace.visibility"
  };
  std::unique_ptr<Stage> stage;
  std::vector<Edge> edges;
};

// Defined in stages/registry.cpp: thesis Algorithm 1 in order, then the other methods.
std::vector<StageEntry> makeRegistry();

// Tests only: one more registry line, appended by every later makeRegistry() after the
// registry's own, so that a method defined in a test reaches every pipeline the program
// builds (the window's, the bench's, a lesson's). A test's registry line is
//   const bool registered = registerTestStage(makeMyStage);
// at file scope. Returns true. The program itself registers nothing here.
using StageFactory = std::unique_ptr<Stage> (*)();
bool registerTestStage(StageFactory make, std::vector<StageEntry::Edge> edges = {});

struct StageTime {
  std::string stage;
  bool ran = false;          // false: not needed by the requested outputs ("not run")
  double milliseconds = 0;   // this run (0 when not run)
  double median = 0;         // over `runs` runs with identical parameters, scene and size
  int runs = 0;
};

class Pipeline {
public:
  Pipeline();  // makeRegistry()
  // Throws std::invalid_argument naming the stage and slot for a missing or ambiguous
  // producer, a format mismatch or a cycle.
  explicit Pipeline(std::vector<StageEntry> registry);

  // Stages in execution order (derived from the edges; registry order among equals).
  const std::vector<std::unique_ptr<Stage>>& stages() const { return stages_; }
  Stage& stage(const std::string& name) const;  // throws naming the valid stages
  bool hasStage(const std::string& name) const;
  Param& param(const std::string& stageDotKey) const;  // throws naming the valid keys
  std::vector<std::string> paramKeys() const;
  // "stage.key=value": returns "" or a message naming the valid keys or range.
  std::string set(const std::string& assignment);

  // Stages whose output carries `role` (kRoleShadowMethod, kRoleGroundTruth), in order;
  // the method's visibility is "<stage>.<output>" as methodOutput() gives it.
  std::vector<std::string> methods(unsigned role = kRoleShadowMethod) const;
  std::string methodOutput(const std::string& method) const;  // "filter" -> "filter.visibility"

  // The producer "stage.output" wired to `slot` of `stage` under the current parameters;
  // "" for a choice slot set to "none".
  std::string source(const std::string& stage, const std::string& slot) const;
  // Every stage that `outputs` ("stage.output") depend on under the current parameters,
  // the producers themselves included, in execution order.
  std::vector<std::string> dependencies(const std::vector<std::string>& outputs) const;
  std::vector<std::string> allOutputs() const;  // every texture output, "stage.output"

  // Runs the stages that `requested` depends on (all stages when empty), timing each with
  // GL_TIME_ELAPSED queries on a GPU, glFinish + steady clock on llvmpipe (where the queries
  // are wrong): timing(). The per-frame camera uniforms are filled first.
  void run(Frame& frame, const std::vector<std::string>& requested = {});
  // One entry per stage in order; stages the last run skipped have ran == false.
  const std::vector<StageTime>& lastTimes() const { return times_; }
  const StageTime& lastTime(const std::string& stage) const;
  // How stage times are taken: Auto picks Queries unless the renderer is llvmpipe.
  enum class Timing { Auto, Finish, Queries };
  void setTiming(Timing timing) { timing_ = timing; }
  // "GL_TIME_ELAPSED" or "glFinish + steady clock" (after a context exists).
  std::string timingMethod() const;
  ~Pipeline();

  // Changes whenever any parameter changes (a fingerprint of every value and auto flag; an
  // auto parameter's value is not a setting): the window re-runs when it differs from the
  // revision of its last run.
  std::uint64_t revision() const;

  // The graph in Graphviz dot: stages as nodes, wired slots as edges (choice slots dashed).
  std::string dot() const;

private:
  struct Wire {
    std::string consumer, slot;
    std::vector<std::string> sources;  // one for a fixed edge; every candidate for a choice
  };
  void wire(std::vector<StageEntry>& registry);
  void order();
  void checkAutoChoices() const;
  bool decideAutoChoices(Frame& frame, const std::string& after, std::set<std::string>& undecided);
  std::string choiceKey(const std::string& stage, const Input& input) const;
  std::vector<std::string> closure(const std::vector<std::string>& outputs,
                                   const std::set<std::string>& undecided) const;
  void prepareCamera(Frame& frame) const;
  const Wire& wireOf(const std::string& stage, const std::string& slot) const;
  std::string timingKey(const Frame& frame) const;

  std::vector<std::unique_ptr<Stage>> stages_;
  std::vector<Wire> wires_;
  std::vector<StageTime> times_;
  Timing timing_ = Timing::Auto;
  std::vector<GLuint> queries_;  // one GL_TIME_ELAPSED query per stage, made on first use
  std::string seriesKey_;
  std::map<std::string, std::vector<double>> series_;  // per stage, identical settings
};
