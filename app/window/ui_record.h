// The window's Record (decision 130): the outputs the views show, over a time range of the
// animated scene at a frame rate, written as `penumbra export --time-range` writes them
// (app/export/video_export.h): numbered EXR + PNG per output, the views side by side, an
// MP4 and a GIF each, run.json last, one transaction. Opened from the timeline's "Record"
// button. Each UI frame records one frame: the scene is posed at the frame's time
// (Session::setTime), the window's own run computes what the views show (so the views
// play the recording as it is written), and the frame is written; a progress bar and
// Cancel show meanwhile (Cancel: nothing written). Encoding, at the end, shows the run
// overlay's bar and Cancel.
#pragma once
#include <glm/glm.hpp>

#include <memory>
#include <string>

class UiState;
class VideoExport;

// The Record window's settings and the recording under way (UiState::panelMemory).
struct RecordingState {
  bool windowOpen = false;
  bool initialised = false;  // the range follows the first animated scene shown
  float start = 0, end = 4, fps = 24;
  bool sideBySide = true, videos = true;
  std::string directory;
  // Under way (the one owner: reset, it removes its temporary directory):
  std::shared_ptr<VideoExport> exporter;
  int next = 0;           // the frame being recorded
  bool posed = false;     // the scene is posed at frame `next`'s time
  bool cancel = false;
  double savedTime = 0;
  bool savedPlaying = false;
  std::string target, result;
};

// The timeline's button that opens the Record window (app/window/ui_timeline.cpp).
void drawRecordButton(UiState& state);
// The Record window, when open (drawUi, app/window/window_app.cpp).
void drawRecordWindow(UiState& state);
// Whether a recording is under way (the main loop then polls instead of waiting).
bool recordingActive(const UiState& state);
// The frame loop's run (outside the UI frame; UiState::runIfNeeded), and around it while
// recording: before, the scene posed at the next frame's time; after, that frame written
// once the views hold it at full resolution. Returns whether it ran.
bool runRecordingFrame(UiState& state, glm::ivec2 viewRegion);
