// The "Temporal" tab of the side panel (docs/decisions/120-temporal-stability.md): a time plot
// of the last frames' temporal change of every shadow method the views show, while the
// timeline plays (or, with a new frame key per run, on a static scene): per run, the mean
// |visibility - visibility of the run before| over the pixels counted in both runs whose
// ground truth did not change (app/stats/temporal.h). The ground truth is the one the
// comparison is set against (error.against) when it ran this run and the run before; without
// it every counted pixel counts as stable and the panel says so.
#pragma once
#include <cstdint>
#include <deque>
#include <map>
#include <string>
#include <vector>

#include "stats/temporal.h"

class UiState;

// What the tab keeps between window frames (UiState::panelMemory.temporal).
struct TemporalPanelState {
  struct Series {
    std::vector<float> previous;  // the method's visibility in the last recorded run
    std::deque<float> change;     // per recorded pair, oldest first: mean |change| (stable pixels)
    std::deque<float> worstPixel; // per recorded pair: the largest single pixel's |change|
  };
  int capacity = 120;            // pairs kept in the plot
  bool perFrameKey = false;      // move the frame key after every run (Monte Carlo swims)
  int lastRuns = -1, sceneLoads = -1;
  int keyMovedAfterRun = -1;     // the run after which the frame key was last moved
  int width = 0, height = 0;     // eye size of the last recorded run
  bool previousHadTruth = false;
  std::vector<float> previousTruth;
  std::vector<std::uint8_t> previousCounted;
  std::map<std::string, Series> series;  // method -> its points
  std::deque<float> truthChange;         // the ground truth's own change per pair
  std::string truthOutput;               // "" when no ground truth was used
  TemporalChange last;                   // the last pair of the first method (pixel counts)
};

// After each window frame's run: records a new point when the pipeline ran (called every
// frame, whether the tab is shown or not); with "new key every run" on, moves the frame key.
void stepTemporalPanel(UiState& state);
// The tab's contents, drawn into the current window.
void drawTemporalPanel(UiState& state);
// For lesson texts (lessons/README.md): {temporal:METHOD} the mean of the kept pairs' change
// of METHOD ("truth": the ground truth's own change); {temporal_pixel:METHOD} the largest
// single pixel's change over them; {temporal_spread:METHOD} their standard deviation over
// their mean (a shadow that moves evenly has a small spread; a coarse map's texels that
// stand still and then pop have a large one: docs/temporal.md). False, with the reason,
// when no pair was measured.
enum class TemporalNumber { Mean, WorstPixel, Spread };
bool temporalNumber(const UiState& state, const std::string& method, TemporalNumber kind, double& value,
                    std::string& problem);
// Script actions {"temporal_clear": true} and {"temporal_key": bool} (the tab's Clear button
// and its "new frame key every run" box).
void clearTemporalPanel(UiState& state);
void setTemporalPerFrameKey(UiState& state, bool on);
