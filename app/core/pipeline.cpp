#include "core/pipeline.h"
#include "core/run_control.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <set>
#include <stdexcept>
#include <tuple>

#include "scene/eye_frustum.h"

namespace {

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

// The choice slot of `owner` that its own parameter `key` selects (not a following slot).
const Input& decidingInput(const Stage& owner, const std::string& key) {
  for (const Input& input : owner.inputs())
    if (input.isChoice() && !input.followsChoice() && input.choiceParam == key) return input;
  throw std::logic_error("stage '" + owner.name() + "': no choice slot selected by '" + key + "'");
}

std::string formatName(GLenum format) {
  switch (format) {
    case kBufferFormat: return "buffer";
    case GL_R32F: return "R32F";
    case GL_RG32F: return "RG32F";
    case GL_RGBA32F: return "RGBA32F";
    case GL_RGBA8: return "RGBA8";
    case GL_DEPTH_COMPONENT32F: return "DEPTH32F";
    default: return "format 0x" + std::to_string(format);
  }
}

}  // namespace

Pipeline::Pipeline() : Pipeline(makeRegistry()) {}

Pipeline::Pipeline(std::vector<StageEntry> registry) {
  for (StageEntry& entry : registry) {
    if (!entry.stage) throw std::invalid_argument("registry: empty stage entry");
    if (hasStage(entry.stage->name()))
      throw std::invalid_argument("registry: two stages named '" + entry.stage->name() + "'");
    checkCapabilities(*entry.stage);  // what each declared capability promises is there
    stages_.push_back(std::move(entry.stage));
  }
  wire(registry);
  order();
  checkAutoChoices();
}

// 1. Wiring: every input slot gets its producer(s); a missing or ambiguous producer or a
//    format mismatch is an error naming the stage and slot.
void Pipeline::wire(std::vector<StageEntry>& registry) {
  std::map<std::string, const std::vector<StageEntry::Edge>*> edgesOf;
  for (size_t i = 0; i < registry.size(); ++i) edgesOf[stages_[i]->name()] = &registry[i].edges;

  for (const auto& consumer : stages_) {
    const std::string where = "stage '" + consumer->name() + "'";
    const auto& edges = *edgesOf.at(consumer->name());
    for (const StageEntry::Edge& edge : edges) {
      const auto& in = consumer->inputs();
      if (std::none_of(in.begin(), in.end(), [&](const Input& i) { return i.name == edge.slot; }))
        throw std::invalid_argument("registry: " + where + " has no input slot '" + edge.slot + "'");
    }
    for (const Input& input : consumer->inputs()) {
      const std::string slot = where + ", input '" + input.name + "'";
      Wire wire{consumer->name(), input.name, {}};
      if (input.followsChoice()) {
        // A slot following another stage's choice: the same candidates, checked below.
        for (const auto& producer : stages_)
          for (const Output& output : producer->outputs())
            if (producer.get() != consumer.get() && (output.roles & input.chooseRole))
              wire.sources.push_back(producer->name() + "." + output.name);
      } else if (input.isChoice()) {
        // A choice slot: every output carrying the role, one option per producing stage.
        Param& choice = consumer->param(input.choiceParam);
        choice.options.clear();
        for (const auto& producer : stages_) {
          if (producer.get() == consumer.get()) continue;
          for (const Output& output : producer->outputs()) {
            if (!(output.roles & input.chooseRole)) continue;
            if (output.format != input.format)
              throw std::invalid_argument(slot + ": candidate " + producer->name() + "." +
                                          output.name + " is " + formatName(output.format) +
                                          ", the slot needs " + formatName(input.format));
            if (std::find(choice.options.begin(), choice.options.end(), producer->name()) !=
                choice.options.end())
              throw std::invalid_argument("stage '" + producer->name() +
                                          "' has two outputs with the same role");
            choice.options.push_back(producer->name());
            wire.sources.push_back(producer->name() + "." + output.name);
          }
        }
        if (input.allowNone) choice.options.push_back("none");
        if (choice.options.empty())
          throw std::invalid_argument(slot + ": no stage produces an output with its role");
        auto initial = std::find(choice.options.begin(), choice.options.end(), input.defaultChoice);
        choice.value = initial == choice.options.end() ? 0 : double(initial - choice.options.begin());
        choice.type = Param::Type::Enum, choice.min = 0;
        choice.max = double(choice.options.size() - 1);
      } else {
        // A fixed slot: the registry's edge, else the one output of the slot's name.
        std::string source;
        for (const StageEntry::Edge& edge : edges)
          if (edge.slot == input.name) source = edge.source;
        if (source.empty()) {
          std::vector<std::string> found;
          for (const auto& producer : stages_)
            for (const Output& output : producer->outputs())
              if (producer.get() != consumer.get() && output.name == input.name)
                found.push_back(producer->name() + "." + output.name);
          if (found.empty())
            throw std::invalid_argument(slot + ": no stage has an output named '" + input.name +
                                        "' (wire it in stages/registry.cpp)");
          if (found.size() > 1)
            throw std::invalid_argument(slot + ": ambiguous, several producers (" + joined(found) +
                                        "); name one in stages/registry.cpp");
          source = found.front();
        }
        const size_t dot = source.find('.');
        if (dot == std::string::npos || !hasStage(source.substr(0, dot)))
          throw std::invalid_argument(slot + ": unknown producer '" + source + "'");
        const Stage& producer = stage(source.substr(0, dot));
        const auto& outs = producer.outputs();
        auto output = std::find_if(outs.begin(), outs.end(),
                                   [&](const Output& o) { return o.name == source.substr(dot + 1); });
        if (output == outs.end())
          throw std::invalid_argument(slot + ": stage '" + producer.name() +
                                      "' has no output '" + source.substr(dot + 1) + "'");
        const bool wantBuffer = input.format == kBufferFormat;
        if (wantBuffer != output->isBuffer() || (input.format != 0 && input.format != output->format))
          throw std::invalid_argument(slot + ": format mismatch, " + source + " is " +
                                      formatName(output->format) + ", the slot needs " +
                                      (input.format ? formatName(input.format) : "a texture"));
        wire.sources.push_back(source);
      }
      wires_.push_back(std::move(wire));
    }
  }
  // 1b. A following slot lists the same producers as the choice it follows (in order).
  for (const Wire& wire : wires_) {
    const Input& input = stage(wire.consumer).input(wire.slot);
    if (!input.followsChoice()) continue;
    const std::string slot = "stage '" + wire.consumer + "', input '" + wire.slot + "'";
    Param* followed = nullptr;
    try {
      followed = &param(input.choiceParam);
    } catch (const std::out_of_range&) {
      throw std::invalid_argument(slot + ": follows '" + input.choiceParam +
                                  "', which is no parameter");
    }
    std::vector<std::string> names;
    for (const std::string& source : wire.sources) names.push_back(source.substr(0, source.find('.')));
    if (input.allowNone) names.push_back("none");
    if (followed->type != Param::Type::Enum || followed->options != names)
      throw std::invalid_argument(slot + ": its candidates (" + joined(names) + ") are not the "
                                  "options of '" + input.choiceParam + "', which it follows");
    for (const std::string& source : wire.sources)
      if (stage(source.substr(0, source.find('.'))).output(source.substr(source.find('.') + 1))
              .format != input.format)
        throw std::invalid_argument(slot + ": candidate " + source + " has another format");
  }
}

// 2. Execution order: a topological order of every possible edge (each choice slot counts
//    all its candidates, so any choice runs in a valid order); registry order among equals.
void Pipeline::order() {
  const size_t n = stages_.size();
  std::map<std::string, size_t> index;
  for (size_t i = 0; i < n; ++i) index[stages_[i]->name()] = i;
  std::vector<std::set<size_t>> consumers(n);
  std::vector<int> pending(n, 0);
  for (const Wire& wire : wires_)
    for (const std::string& source : wire.sources) {
      const size_t from = index.at(source.substr(0, source.find('.'))), to = index.at(wire.consumer);
      if (consumers[from].insert(to).second) ++pending[to];
    }
  std::vector<size_t> ordered;
  std::vector<bool> done(n, false);
  while (ordered.size() < n) {
    size_t next = n;
    for (size_t i = 0; i < n && next == n; ++i)
      if (!done[i] && pending[i] == 0) next = i;
    if (next == n) {
      std::vector<std::string> cycle;
      for (size_t i = 0; i < n; ++i)
        if (!done[i]) cycle.push_back(stages_[i]->name());
      throw std::invalid_argument("stage graph has a cycle among: " + joined(cycle));
    }
    done[next] = true;
    ordered.push_back(next);
    for (size_t to : consumers[next]) --pending[to];
  }
  std::vector<std::unique_ptr<Stage>> sorted;
  for (size_t i : ordered) sorted.push_back(std::move(stages_[i]));
  stages_ = std::move(sorted);
  times_.clear();
  for (const auto& stage : stages_) times_.push_back({stage->name()});
}

// 3. An `auto` choice (Input::decidedAfter) is decided after a stage that its consumer, and
//    every slot following it, depend on through fixed edges: so the decision comes before
//    any of them reads it, whatever else is chosen.
void Pipeline::checkAutoChoices() const {
  // Over fixed edges only: an undecided choice leads nowhere (run()).
  std::map<std::string, std::set<std::string>> upstream;
  for (const auto& consumer : stages_) {  // execution order: producers come first
    std::set<std::string>& above = upstream[consumer->name()];
    for (const Wire& wire : wires_)
      if (wire.consumer == consumer->name() && !consumer->input(wire.slot).isChoice())
        for (const std::string& source : wire.sources) {
          const std::string producer = source.substr(0, source.find('.'));
          above.insert(producer);
          above.insert(upstream[producer].begin(), upstream[producer].end());
        }
  }
  for (const Wire& wire : wires_) {
    const Input& input = stage(wire.consumer).input(wire.slot);
    if (!input.isChoice()) continue;
    const std::string choice = choiceKey(wire.consumer, input);  // "owner.key"
    const Stage& owner = stage(choice.substr(0, choice.find('.')));
    const std::string key = choice.substr(choice.find('.') + 1);
    if (!owner.param(key).allowsAuto) continue;
    const std::string slot = "stage '" + wire.consumer + "', input '" + wire.slot + "'";
    const std::string& after = decidingInput(owner, key).decidedAfter;
    if (after.empty() || !hasStage(after))
      throw std::invalid_argument(slot + ": its choice '" + owner.name() + "." + key +
                                  "' allows auto but names no stage to decide it after "
                                  "(Input::decidedAfter: '" + after + "')");
    if (!upstream[wire.consumer].count(after))
      throw std::invalid_argument(slot + ": its choice '" + owner.name() + "." + key +
                                  "' is auto, decided after '" + after + "', which the slot's "
                                  "stage does not depend on");
  }
}

bool Pipeline::hasStage(const std::string& name) const {
  return std::any_of(stages_.begin(), stages_.end(),
                     [&](const auto& stage) { return stage && stage->name() == name; });
}

Stage& Pipeline::stage(const std::string& name) const {
  for (const auto& stage : stages_)
    if (stage->name() == name) return *stage;
  std::vector<std::string> valid;
  for (const auto& stage : stages_) valid.push_back(stage->name());
  throw std::out_of_range("unknown stage '" + name + "'; valid: " + joined(valid));
}

std::vector<std::string> Pipeline::paramKeys() const {
  std::vector<std::string> keys;
  for (const auto& stage : stages_)
    for (const Param& param : stage->params()) keys.push_back(stage->name() + "." + param.key);
  return keys;
}

Param& Pipeline::param(const std::string& stageDotKey) const {
  const size_t dot = stageDotKey.find('.');
  if (dot != std::string::npos) {
    for (const auto& stage : stages_)
      if (stage->name() == stageDotKey.substr(0, dot))
        for (Param& param : stage->params())
          if (param.key == stageDotKey.substr(dot + 1)) return param;
  }
  throw std::out_of_range("unknown parameter '" + stageDotKey + "'; valid keys: " +
                          joined(paramKeys()));
}

std::string Pipeline::set(const std::string& assignment) {
  const size_t equals = assignment.find('=');
  if (equals == std::string::npos)
    return "'" + assignment + "' is not of the form stage.key=value";
  try {
    const std::string key = assignment.substr(0, equals);
    const std::string problem = param(key).set(assignment.substr(equals + 1));
    return problem.empty() ? "" : key + ": " + problem;
  } catch (const std::out_of_range& error) {
    return error.what();
  }
}

std::vector<std::string> Pipeline::methods(unsigned role) const {
  std::vector<std::string> names;
  for (const auto& stage : stages_)
    for (const Output& output : stage->outputs())
      if (output.roles & role) {
        names.push_back(stage->name());
        break;
      }
  return names;
}

std::string Pipeline::methodOutput(const std::string& method) const {
  for (const Output& output : stage(method).outputs())
    if (output.roles != kRoleNone) return method + "." + output.name;
  throw std::out_of_range("stage '" + method + "' is not a shadow method; methods: " +
                          joined(methods(kRoleShadowMethod | kRoleGroundTruth)));
}

const Pipeline::Wire& Pipeline::wireOf(const std::string& stage, const std::string& slot) const {
  for (const Wire& wire : wires_)
    if (wire.consumer == stage && wire.slot == slot) return wire;
  throw std::out_of_range("stage '" + stage + "' has no input slot '" + slot + "'");
}

std::string Pipeline::source(const std::string& stageName, const std::string& slot) const {
  const Wire& wire = wireOf(stageName, slot);
  const Input& input = stage(stageName).input(slot);
  if (!input.isChoice()) return wire.sources.front();
  const std::string& chosen = input.followsChoice()
                                  ? param(input.choiceParam).asEnum()
                                  : stage(stageName).param(input.choiceParam).asEnum();
  return chosen == "none" ? "" : methodOutput(chosen);
}

std::vector<std::string> Pipeline::dependencies(const std::vector<std::string>& outputs) const {
  return closure(outputs, {});
}

// The choice parameter ("stage.key") that selects a choice slot's producer.
std::string Pipeline::choiceKey(const std::string& stageName, const Input& input) const {
  return input.followsChoice() ? input.choiceParam : stageName + "." + input.choiceParam;
}

std::vector<std::string> Pipeline::closure(const std::vector<std::string>& outputs,
                                           const std::set<std::string>& undecided) const {
  std::set<std::string> needed;
  std::function<void(const std::string&)> visit = [&](const std::string& stageName) {
    if (!needed.insert(stageName).second) return;
    for (const Input& input : stage(stageName).inputs()) {
      if (input.isChoice() && undecided.count(choiceKey(stageName, input))) continue;
      const std::string producer = source(stageName, input.name);
      if (!producer.empty()) visit(producer.substr(0, producer.find('.')));
    }
  };
  for (const std::string& output : outputs) visit(output.substr(0, output.find('.')));
  std::vector<std::string> ordered;
  for (const auto& stage : stages_)
    if (needed.count(stage->name())) ordered.push_back(stage->name());
  return ordered;
}

std::vector<std::string> Pipeline::allOutputs() const {
  std::vector<std::string> keys;
  for (const auto& stage : stages_)
    for (const Output& output : stage->outputs())
      if (!output.isBuffer()) keys.push_back(stage->name() + "." + output.name);
  return keys;
}

std::uint64_t Pipeline::revision() const {
  std::uint64_t hash = 1469598103934665603ull;  // FNV-1a over every key, value and auto flag
  auto mix = [&](const void* data, size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < bytes; ++i) hash = (hash ^ p[i]) * 1099511628211ull;
  };
  for (const auto& stage : stages_)
    for (const Param& param : stage->params()) {
      mix(param.key.data(), param.key.size());
      // auto and a fixed value differ; under auto the value is what the last frame chose
      // (an auto choice writes it while running), not a setting.
      const unsigned char automatic = param.automatic;
      mix(&automatic, 1);
      if (!automatic) mix(&param.value, sizeof param.value);
    }
  return hash;
}

const StageTime& Pipeline::lastTime(const std::string& stageName) const {
  for (const StageTime& time : times_)
    if (time.stage == stageName) return time;
  stage(stageName);  // throws naming the valid stages
  throw std::logic_error("no timing slot for stage " + stageName);
}

// The eye camera (Algorithm 1's eye pass) and the per-frame key: the only uniforms that are
// not a stage's output.
void Pipeline::prepareCamera(Frame& frame) const {
  const Scene& scene = frame.scene;
  gpu::FrameUniforms& u = frame.uniforms;
  const float aspect = float(frame.eyeWidth) / float(frame.eyeHeight);
  const EyeDepthRange eyeDepths = eyeDepthRangeOrWarn(scene, aspect);  // scene/eye_frustum.h
  const float eyeNear = eyeDepths.eyeNear, eyeFar = eyeDepths.eyeFar;
  const glm::mat4 viewFromWorld =
      glm::lookAt(scene.camera.position, scene.camera.target, scene.camera.up);
  const glm::mat4 clipFromView =
      glm::perspective(glm::radians(scene.camera.fovYDegrees), aspect, eyeNear, eyeFar);
  u.clipFromWorld = clipFromView * viewFromWorld;
  u.worldFromClip = glm::inverse(u.clipFromWorld);
  u.wsEyePosition = glm::vec4(scene.camera.position, 1);
  u.sizes = glm::uvec4(frame.eyeWidth, frame.eyeHeight, 0, 0);
  u.keys = glm::uvec4(frame.frameKey, 0, 0, 0);
  frame.uniformBuffer.upload(&u, sizeof u);
  glBindBufferBase(GL_UNIFORM_BUFFER, binding::kFrameUniforms, frame.uniformBuffer.id());
}

std::string Pipeline::timingKey(const Frame& frame) const {
  return std::to_string(revision()) + "/" + frame.scene.name + "/" +
         std::to_string(frame.eyeWidth) + "x" + std::to_string(frame.eyeHeight);
}

void Pipeline::run(Frame& frame, const std::vector<std::string>& requested) {
  // 1. What runs: the dependency closure of the requested outputs (everything if none). An
  //    `auto` choice not yet decided this frame leads nowhere: a stage needed only through
  //    it waits for the decision.
  std::set<std::string> undecided;
  for (const auto& owner : stages_)
    for (const Input& input : owner->inputs())
      if (input.isChoice() && !input.followsChoice() && owner->param(input.choiceParam).automatic)
        undecided.insert(choiceKey(owner->name(), input));
  auto stagesNeeded = [&] {
    std::vector<std::string> needed;
    if (requested.empty()) {
      for (const auto& stage : stages_) needed.push_back(stage->name());
    } else {
      needed = closure(requested, undecided);
    }
    return std::set<std::string>(needed.begin(), needed.end());
  };
  std::set<std::string> willRun = stagesNeeded();
  frame.requested = std::set<std::string>(requested.begin(), requested.end());
  frame.partial.clear();

  // 2. A new timing series whenever parameters, scene or size change.
  const std::string key = timingKey(frame);
  if (key != seriesKey_) series_.clear(), seriesKey_ = key;

  prepareCamera(frame);
  frame.counters.clear();
  frame.readbacks.clear();
  const bool queries = timingMethod() == "GL_TIME_ELAPSED";
  if (queries && queries_.empty()) {
    queries_.resize(stages_.size());
    glCreateQueries(GL_TIME_ELAPSED, GLsizei(queries_.size()), queries_.data());
  }
  glFinish();
  // 3. One stage, timed: with timer queries, their results are read after the last stage
  //    (5.), so no stage waits for the GPU; otherwise glFinish and the clock.
  std::vector<size_t> timed;
  auto record = [&](size_t i, double milliseconds) {
    StageTime& time = times_[i];
    std::vector<double>& runs = series_[stages_[i]->name()];
    runs.push_back(milliseconds);
    std::vector<double> sorted = runs;
    std::nth_element(sorted.begin(), sorted.begin() + long(sorted.size() / 2), sorted.end());
    time.ran = true, time.milliseconds = milliseconds;
    time.median = sorted[sorted.size() / 2], time.runs = int(runs.size());
  };
  auto runStage = [&](size_t i) {
    Stage& stage = *stages_[i];
    throwIfRunCancelled("before stage " + stage.name());  // core/run_control.h
    const auto start = std::chrono::steady_clock::now();
    if (queries) glBeginQuery(GL_TIME_ELAPSED, queries_[i]);
    stage.run(frame);
    if (queries) {
      glEndQuery(GL_TIME_ELAPSED);
      timed.erase(std::remove(timed.begin(), timed.end(), i), timed.end());
      timed.push_back(i);
      times_[i].ran = true;
      return;
    }
    glFinish();
    record(i, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                  .count());
  };
  // 4. In order; a stage not needed loses its old outputs, so nothing downstream or on
  //    screen is stale. After a stage that decides `auto` choices, what is needed is worked
  //    out again, and a stage skipped before the decision but needed after it runs then
  //    (its producers come before it, so they have run).
  for (size_t i = 0; i < stages_.size(); ++i) {
    Stage& stage = *stages_[i];
    if (!willRun.count(stage.name())) {
      for (const Output& output : stage.outputs()) {
        frame.textures.erase(stage.name() + "." + output.name);
        frame.buffers.erase(stage.name() + "." + output.name);
      }
      times_[i].ran = false, times_[i].milliseconds = 0;
      continue;
    }
    runStage(i);
    if (!decideAutoChoices(frame, stage.name(), undecided)) continue;
    willRun = stagesNeeded();
    for (size_t j = 0; j < i; ++j)
      if (willRun.count(stages_[j]->name()) && !times_[j].ran) runStage(j);
  }
  throwIfRunCancelled("after the last stage");  // one that stopped early left partial data
  // 5. After the last stage, the one wait for the GPU: the stages' read-backs (counters,
  //    recorded steps; Frame::readAfterFrame) and the timer queries.
  frame.finishReadbacks();
  for (size_t i : timed) {
    GLuint64 nanoseconds = 0;
    glGetQueryObjectui64v(queries_[i], GL_QUERY_RESULT, &nanoseconds);
    record(i, double(nanoseconds) * 1e-6);
  }
}

// The `auto` choices decided after stage `after`: each parameter takes the option its
// stage's rule gives (its value, so source() and the window read it) and leaves
// `undecided`; the reason goes to the frame's auto reasons. Whether any was decided.
bool Pipeline::decideAutoChoices(Frame& frame, const std::string& after,
                                 std::set<std::string>& undecided) {
  bool decided = false;
  for (const auto& owner : stages_)
    for (const Input& input : owner->inputs()) {
      if (!input.isChoice() || input.followsChoice() || input.decidedAfter != after) continue;
      Param& choice = owner->param(input.choiceParam);
      if (!choice.automatic) continue;
      const AutoChoice chosen = owner->chooseAuto(input.choiceParam, frame);
      const auto option = std::find(choice.options.begin(), choice.options.end(), chosen.option);
      if (option == choice.options.end())
        throw std::logic_error(owner->name() + "." + choice.key + ": auto chose '" +
                               chosen.option + "', which is not an option");
      choice.value = double(option - choice.options.begin());
      undecided.erase(choiceKey(owner->name(), input));
      frame.autoReasons.push_back(chosen.reason);
      decided = true;
    }
  return decided;
}

std::string Pipeline::timingMethod() const {
  Timing timing = timing_;
  if (timing == Timing::Auto) {
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    timing = renderer && !std::strstr(renderer, "llvmpipe") ? Timing::Queries : Timing::Finish;
  }
  return timing == Timing::Queries ? "GL_TIME_ELAPSED" : "glFinish + steady clock";
}

Pipeline::~Pipeline() {
  if (!queries_.empty()) glDeleteQueries(GLsizei(queries_.size()), queries_.data());
}

std::string Pipeline::dot() const {
  std::string text = "digraph penumbra {\n  rankdir=LR;\n  node [shape=box, fontname=\"sans\"];\n"
                     "  edge [fontname=\"sans\", fontsize=10];\n";
  for (const auto& stage : stages_) {
    std::string style;
    for (const Output& output : stage->outputs())
      if (output.roles != kRoleNone) style = ", style=bold";  // a method or ground truth
    text += "  \"" + stage->name() + "\" [label=\"" + stage->name() + "\"" + style + "];\n";
  }
  // One edge per (producer, consumer, kind), labelled with every slot it feeds; a choice
  // slot's candidates are dashed.
  std::map<std::tuple<std::string, std::string, bool>, std::vector<std::string>> edges;
  for (const Wire& wire : wires_) {
    const bool choice = stage(wire.consumer).input(wire.slot).isChoice();
    for (const std::string& source : wire.sources) {
      const std::string output = source.substr(source.find('.') + 1);
      edges[{source.substr(0, source.find('.')), wire.consumer, choice}].push_back(
          output == wire.slot ? output : output + " : " + wire.slot);
    }
  }
  for (const auto& [key, labels] : edges) {
    const auto& [producer, consumer, choice] = key;
    text += "  \"" + producer + "\" -> \"" + consumer + "\" [label=\"" + joined(labels) + "\"" +
            (choice ? ", style=dashed" : "") + "];\n";
  }
  return text + "}\n";
}
