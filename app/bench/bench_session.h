// The start the headless measuring commands share: a GL context, then the scene on the GPU.
// On failure it prints "penumbra <command>: <why>" and says the exit status the command
// returns (1: no GL context, an internal failure; 2: a bad scene, the user's input).
#pragma once
#include <memory>
#include <string>

#include "gl/gl_context.h"
#include "gl/gpu_scene.h"
#include "scene/scene.h"

struct BenchSession {
  std::unique_ptr<GlContext> context;
  Scene scene;
  std::unique_ptr<GpuScene> gpuScene;
};

// 0 when `session` is ready, else the exit status (the message already printed).
int openBenchSession(const std::string& command, const std::string& sceneName, BenchSession& session);
