// The "Speed vs error" panel's state (window/panels/ui_speed_error.cpp), a part of UiState:
// the live run and a loaded results.json, kept from one UI frame to the next here rather
// than in a function static, so that each UiState (a test's included) starts from the
// defaults and its live run's GL objects die with it, before the GL context.
#pragma once
#include <string>
#include <vector>

#include "bench/bench_json.h"
#include "bench/live_bench.h"

struct SpeedErrorPanelState {
  bool initialised = false;  // the results.json path is filled on first use
  bool live = true;          // showing the live run (else the loaded file)
  LiveBench bench;
  int preset = 1;            // index into the live run's presets (all but animated): "minimal"
  std::string liveMessage;
  char path[512] = "";
  std::string loadedPath, fileMessage;
  BenchRunInfo fileInfo;
  std::vector<BenchSetupInfo> fileSetups;
  std::vector<BenchResult> fileResults;
  int fileSetup = 0;
};
