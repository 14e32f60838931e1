// The stages in execution order (thesis Algorithm 1, deferred form; DESIGN.md §2), their
// parameters addressed as "stage.key", and per-stage timing.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/frame.h"
#include "core/stage.h"

// Defined in stages/registry.cpp: the list of stages, in order.
std::vector<std::unique_ptr<Stage>> makeStages();

struct StageTime {
  std::string stage;
  double milliseconds;
};

class Pipeline {
public:
  Pipeline() : stages_(makeStages()) {}

  const std::vector<std::unique_ptr<Stage>>& stages() const { return stages_; }
  Stage& stage(const std::string& name) const;  // throws naming the valid stages
  Param& param(const std::string& stageDotKey) const;  // throws naming the valid keys
  std::vector<std::string> paramKeys() const;
  // "stage.key=value": returns "" or a message naming the valid keys or range.
  std::string set(const std::string& assignment);

  // Fills the per-frame uniforms (camera, light frame of Eq 3.1) and runs every stage,
  // timing each with glFinish + steady clock (GL_TIME_ELAPSED is wrong on llvmpipe).
  void run(Frame& frame);
  const std::vector<StageTime>& lastTimes() const { return times_; }

private:
  void prepare(Frame& frame) const;
  std::vector<std::unique_ptr<Stage>> stages_;
  std::vector<StageTime> times_;
};
