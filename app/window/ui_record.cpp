#include "window/ui_record.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "core/run_control.h"
#include "export/video_export.h"
#include "window/panels/ui_export.h"
#include "window/ui_state.h"
#include "window/ui_widgets.h"

namespace fs = std::filesystem;

namespace {

std::string sanitized(std::string text) {
  for (char& c : text)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '_') c = '-';
  return text;
}

// The outputs the shown views show, each once, in view order.
std::vector<std::string> viewOutputs(const UiState& state) {
  std::vector<std::string> outputs;
  for (int v = 0; v < state.views.shownViews(); ++v) {
    const std::string& output = state.views.panels[size_t(v)].output;
    if (!output.empty() && std::find(outputs.begin(), outputs.end(), output) == outputs.end())
      outputs.push_back(output);
  }
  return outputs;
}

// Session::setTime rebuilds the frame; at the time of the last run the run key would not
// change and the views would stay empty, so the last run is forgotten: the next one runs.
std::string poseAtTime(UiState& state, double t) {
  std::string problem = state.session.setTime(t);
  state.session.lastRun.reset();
  return problem;
}

void stopRecording(UiState& state, const std::string& message, bool ok) {
  RecordingState& recording = state.panelMemory.recording;
  recording.exporter.reset();  // not committed: the temporary directory goes
  recording.posed = false;
  recording.cancel = false;
  poseAtTime(state, recording.savedTime);
  state.session.playing = recording.savedPlaying;
  recording.result = message;
  state.reportResult("record", message, ok);
}

std::string startRecording(UiState& state) {
  RecordingState& recording = state.panelMemory.recording;
  Session& session = state.session;
  if (!session.animated()) return "record: the scene is not animated (nothing moves over time)";
  VideoRequest request;
  request.range = {recording.start, recording.end, recording.fps};
  if (std::string problem = videoRangeProblem(request.range); !problem.empty()) return "record: " + problem;
  request.outputs = viewOutputs(state);
  if (request.outputs.empty()) return "record: no view shows an output";
  if (recording.sideBySide && request.outputs.size() >= 2) request.sideBySide = request.outputs;
  request.encode = recording.videos;
  fs::path target = recording.directory;
  if (target.empty()) target = fs::path(kDefaultExportDirectory) / sanitized(session.scene.name + "_record");
  try {
    checkVideoRequest(request, session.pipeline, "record");
    recording.exporter = std::make_unique<VideoExport>(target.string(), request, session.pipeline);
  } catch (const std::exception& error) {
    return std::string("record: ") + error.what();
  }
  recording.target = fs::absolute(target).string();
  recording.next = 0;
  recording.posed = false;
  recording.cancel = false;
  recording.savedTime = session.time;
  recording.savedPlaying = session.playing;
  session.playing = false;  // the recording sets the time itself
  recording.result.clear();
  return "";
}

// The videos and run.json, after the last frame: ffmpeg runs with the run overlay's
// Cancel (this is outside the UI frame, so the poll hook draws it).
void finishRecording(UiState& state) {
  RecordingState& recording = state.panelMemory.recording;
  clearRunCancel();
  markRunStart();
  setRunProgress("encoding the recording's videos (ffmpeg)");
  nlohmann::json run;
  const Session& session = state.session;
  run["scene"] = session.scene.name;
  run["renderer"] = session.renderer;
  run["eye_size"] = {session.frame->eyeWidth, session.frame->eyeHeight};
  run["frame_key"] = session.frame->frameKey;
  run["recorded_from"] = "the window's views";
  size_t frameFiles = 0;
  try {
    const auto written = recording.exporter->finish(run, frameFiles);
    const int frames = recording.exporter->frames();
    stopRecording(state, "wrote " + std::to_string(frames) + " frames (" + std::to_string(frameFiles) +
                             " files) and " + std::to_string(written.size()) + " more files into " +
                             recording.target, true);
  } catch (const std::exception& error) {
    stopRecording(state, std::string("record failed, nothing written: ") + error.what(), false);
  }
}

}  // namespace

bool recordingActive(const UiState& state) { return state.panelMemory.recording.exporter != nullptr; }

void drawRecordButton(UiState& state) {
  if (ImGui::Button(recordingActive(state) ? "Recording" : "Record"))
    state.panelMemory.recording.windowOpen = true;
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Record the views over a time range: numbered EXR + PNG per frame,\n"
                      "an MP4 and a GIF per view (ffmpeg), like penumbra export --time-range.");
}

namespace {

void beginRecordedFrame(UiState& state) {
  RecordingState& recording = state.panelMemory.recording;
  if (!recording.exporter) return;
  if (recording.cancel) {
    stopRecording(state, "recording cancelled after " + std::to_string(recording.exporter->framesWritten()) +
                             " frames; nothing written", true);  // asked for: not an error
    return;
  }
  if (recording.posed) return;
  const double t = recording.exporter->time(recording.next);
  if (std::string problem = poseAtTime(state, t); !problem.empty()) {
    stopRecording(state, "record failed, nothing written: " + problem, false);
    return;
  }
  recording.posed = true;
}

void endRecordedFrame(UiState& state) {
  RecordingState& recording = state.panelMemory.recording;
  if (!recording.exporter || !recording.posed) return;
  const Session& session = state.session;
  if (!session.runError.empty()) {
    stopRecording(state, "record stopped, nothing written: the run failed (" + session.runError + ")", false);
    return;
  }
  // Only a full-resolution frame that holds every recorded output (not a preview while the
  // camera moves, not before the first run at this time).
  if (session.previewing || !session.lastRun || session.lastRun->time != session.time ||
      !session.runError.empty())
    return;
  for (const std::string& output : recording.exporter->outputs())
    if (!session.frame->has(output)) return;
  try {
    clearRunCancel();
    recording.exporter->writeFrame(recording.next, *session.frame);
  } catch (const std::exception& error) {
    stopRecording(state, std::string("record failed, nothing written: ") + error.what(), false);
    return;
  }
  recording.posed = false;
  if (++recording.next == recording.exporter->frames()) finishRecording(state);
}

}  // namespace

bool runRecordingFrame(UiState& state, glm::ivec2 viewRegion) {
  RecordingState& recording = state.panelMemory.recording;
  beginRecordedFrame(state);
  const bool ran = state.runIfNeeded(viewRegion);
  endRecordedFrame(state);
  return ran;
}

void drawRecordWindow(UiState& state) {
  RecordingState& recording = state.panelMemory.recording;
  if (!recording.windowOpen) return;
  const Session& session = state.session;
  if (!recording.initialised && session.animated()) {
    recording.end = float(session.rest.animation.duration);
    recording.initialised = true;
  }
  ImGui::SetNextWindowSize({uiPixels(380), 0}, ImGuiCond_Appearing);
  if (!ImGui::Begin("Record", &recording.windowOpen, ImGuiWindowFlags_NoSavedSettings)) {
    ImGui::End();
    return;
  }
  const bool busy = recordingActive(state);
  ImGui::BeginDisabled(busy);
  ImGui::SetNextItemWidth(uiPixels(160));
  float range[2] = {recording.start, recording.end};
  if (ImGui::DragFloat2("from, to (s)", range, 0.05f, -1e4f, 1e4f, "%.2f")) {
    recording.start = range[0];
    recording.end = range[1];
  }
  helpMarker("The time range recorded, in seconds of the scene's animation (the timeline's "
             "time). The end is exclusive: 0 to 4 at 24 fps is 96 frames, and a 4 s loop "
             "recorded so plays on without a repeated frame.");
  ImGui::SetNextItemWidth(uiPixels(160));
  ImGui::DragFloat("fps", &recording.fps, 0.5f, 1.0f, float(kMaxVideoFps), "%.1f");
  helpMarker("Frames per second of the recording (1 to 240): the frame times are "
             "from + i / fps.");
  const std::vector<std::string> outputs = viewOutputs(state);
  std::string list;
  for (const std::string& output : outputs) list += (list.empty() ? "" : ", ") + output;
  ImGui::PushTextWrapPos(0);
  ImGui::TextDisabled("records: %s", list.empty() ? "(no view shows an output)" : list.c_str());
  ImGui::PopTextWrapPos();
  helpMarker("What the shown views show, each output once: per frame its raw EXR and a PNG "
             "in the output's display (the range of the first frame, held so frames compare).");
  ImGui::Checkbox("side by side", &recording.sideBySide);
  helpMarker("With two or more views: the views' PNGs composed left to right into one more "
             "frame sequence and video (side_by_side/), for a slide comparing methods.");
  const bool haveFfmpeg = !ffmpegPath().empty();
  if (!haveFfmpeg) recording.videos = false;
  ImGui::BeginDisabled(!haveFfmpeg);
  ImGui::Checkbox("MP4 + GIF", &recording.videos);
  ImGui::EndDisabled();
  helpMarker(haveFfmpeg ? "Per output an MP4 (H.264, yuv420p, even size) and a GIF (one 256-colour "
                          "palette over all frames), made by ffmpeg after the last frame."
                        : "ffmpeg is not installed (apt-get install ffmpeg): only the frames are written.");
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - buttonsWidth({"(?)"}));
  ImGui::InputTextWithHint("##recorddir", "penumbra_exports/<scene>_record", &recording.directory);
  helpMarker("The output directory: new, empty, or an earlier export (it has run.json), which "
             "is replaced as a whole when the recording is complete, never before.");
  ImGui::EndDisabled();
  if (!busy) {
    if (ImGui::Button("Start recording")) {
      if (std::string problem = startRecording(state); !problem.empty()) {
        recording.result = problem;
        state.fail("record", problem);
      } else {
        state.status = "recording " + std::to_string(recording.exporter->frames()) + " frames into " +
                       recording.target;
      }
    }
  } else {
    const int frames = recording.exporter->frames(), done = recording.exporter->framesWritten();
    char text[64];
    std::snprintf(text, sizeof text, "frame %d / %d", done, frames);
    ImGui::ProgressBar(float(done) / float(frames), {ImGui::GetContentRegionAvail().x - buttonsWidth({"Cancel"}), 0}, text);
    ImGui::SameLine();
    if (ImGui::Button(recording.cancel ? "cancelling" : "Cancel")) recording.cancel = true;
  }
  if (!recording.result.empty()) {
    ImGui::PushTextWrapPos(0);
    ImGui::TextDisabled("%s", recording.result.c_str());
    ImGui::PopTextWrapPos();
  }
  ImGui::End();
}
