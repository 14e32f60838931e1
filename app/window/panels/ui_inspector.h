// The right panel: the picked texel's raw values in every output of the same size (every
// level of array outputs), per-stage timings as bars (median of recent runs), the frame's
// counters, and the per-ray march trace of the picked pixel (ui_trace_panel.h hook).
#pragma once
#include <array>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "window/panels/ui_trace_panel.h"

class UiState;

// What the inspector keeps between frames (UiState::PanelMemory::inspector): the pick
// table, read back once per pipeline run and pick, and the picked ray's trace, replayed
// once per run, pick and ray (not every UI frame).
struct InspectorMemory {
  // One row of the pick table: an output (and level) with its raw values at the pick.
  struct PickRow {
    std::string label;
    std::vector<std::string> channelNames;
    std::array<float, 4> values;
    int channelCount;
  };
  std::vector<PickRow> rows;
  int rowsRuns = -1;
  glm::ivec2 rowsPick{-1}, rowsSpace{-1};
  RayTraceInfo trace;
  int traceRuns = -1, traceRay = -1;
  glm::ivec2 tracePick{-1};
};

void drawInspector(UiState& state);
