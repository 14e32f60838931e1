// The visualizer window (GLFW + Dear ImGui): pipeline panel (left), one or two texture views
// (centre), inspector (right), status line (bottom). See app/ui_*.h for each part.
#pragma once
#include <string>
#include <vector>

struct WindowOptions {
  std::string scene = "cube";
  std::vector<std::string> sets;
  std::string screenshot;  // when set (and no script): render `frames` frames, save, exit
  int frames = 3;
  int width = 1280, height = 800;
  std::string config;  // settings JSON applied at start (app/window/script/ui_settings.h), before --set
  std::string script;  // JSON list of UI actions run in order, then exit (app/window/script/ui_script.h)
  std::string exportDirectory;  // --export: where a script's relative exports go
  bool interactiveLesson = false;  // `penumbra lesson FILE`: wait for "Next", stay open
  bool lessonCommand = false;      // `penumbra lesson FILE` (messages say "lesson FILE")
};

// Returns the exit status: 0, 1 (no display / GL failure), 2 (bad scene, --set, --config,
// script, or a script action that failed).
int runWindow(const WindowOptions& options);
