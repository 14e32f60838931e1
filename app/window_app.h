// The visualizer window (GLFW + Dear ImGui): the composite, the stages in pipeline order,
// the selected stage output, its parameters.
#pragma once
#include <string>
#include <vector>

struct WindowOptions {
  std::string scene = "cube";
  std::vector<std::string> sets;
  std::string screenshot;  // when set: render `frames` frames, save the window, exit
  int frames = 3;
  int width = 1280, height = 800;
};

int runWindow(const WindowOptions& options);
