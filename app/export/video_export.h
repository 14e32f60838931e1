// An animation exported for slides (docs/decisions/130-video-export.md, README "Video
// export"): for each frame time of a range, every requested output written as numbered
// EXR + PNG (`<dir>/<stage.output>/frame_0000.exr|png`), optionally the chosen outputs
// composed left to right (`<dir>/side_by_side/frame_0000.png`), then per output, through
// ffmpeg, an MP4 (H.264, yuv420p, even size) and a GIF (palettegen / paletteuse), and
// run.json last. One transaction (io/output_path.h): the directory then holds this export
// entirely, or, after a failure, Ctrl-C, a Cancel or a kill, what it held before.
// Used by `penumbra export --time-range` (app/cli/video_command.h) and the window's Record
// (app/window/ui_record.h); the frames themselves come from the caller (a posed scene each).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/frame.h"
#include "core/pipeline.h"
#include "core/progress.h"
#include "io/output_path.h"

// Frame times: start + i / fps for i in [0, N), N = ceil((end - start) fps): the end is
// exclusive, so a loop of 4 s at 24 fps is 96 frames and its video loops without a
// repeated frame.
struct VideoRange {
  double start = 0, end = 4, fps = 24;
  int frames() const;
  double time(int frame) const;
};
constexpr double kMaxVideoFps = 240;
constexpr int kMaxVideoFrames = 10000;  // frame_0000 .. frame_9999

// "A:B" (seconds) -> the range; InputError naming the flag and what is wrong (end <= start,
// non-finite, fps <= 0 or > 240, more than kMaxVideoFrames frames).
VideoRange parseVideoRange(const std::string& timeRange, double fps);
// The same checks on numbers (the window's fields); "" or the problem.
std::string videoRangeProblem(const VideoRange& range);

// ffmpeg on $PATH, or "".
std::string ffmpegPath();
// What to say when it is missing (the fix named).
std::string missingFfmpegMessage();

struct VideoRequest {
  VideoRange range;
  std::vector<std::string> outputs;     // "stage.output", each written per frame
  std::vector<std::string> sideBySide;  // composed left to right (2 or more), or none
  bool encode = true;                   // the MP4s and GIFs (false: the frames alone)
};
// Known, image outputs only, no repeats; side-by-side ones are added to `outputs`. Throws
// InputError naming the flag.
void checkVideoRequest(VideoRequest& request, const Pipeline& pipeline, const std::string& flag);

class VideoExport {
public:
  // Checks `target` (the output rule) and opens the transaction; nothing is rendered here.
  VideoExport(const std::string& target, VideoRequest request, const Pipeline& pipeline);
  int frames() const { return request_.range.frames(); }
  double time(int frame) const { return request_.range.time(frame); }
  const std::vector<std::string>& outputs() const { return request_.outputs; }
  int framesWritten() const { return written_; }
  // Writes frame `frame` (in order, from 0) of every output. The PNGs keep the display of
  // frame 0 for the whole video (an error's data range would otherwise flicker per frame).
  // Throws InputError for an output the frame lacks or that is an array texture.
  void writeFrame(int frame, const Frame& pipelineFrame);
  // Encodes (ffmpeg, cancellable), writes run.json (`run` plus the video's own fields) and
  // commits. Returns what it wrote (videos, run.json) and the frame count in `frameFiles`.
  std::vector<std::string> finish(nlohmann::json run, size_t& frameFiles);
  // The progress shown for this export: frames, then one step per encode.
  ProgressTask& progress() { return *progress_; }

private:
  void encode(const std::string& name, std::vector<std::string>& written);
  VideoRequest request_;
  const Pipeline& pipeline_;
  std::unique_ptr<DirectoryTransaction> transaction_;
  std::unique_ptr<ProgressTask> progress_;
  std::vector<DisplayHint> hints_;  // per output, fixed at frame 0
  std::vector<std::vector<std::string>> channels_;
  int width_ = 0, height_ = 0;       // of the side-by-side frame
  std::vector<std::pair<int, int>> sizes_;  // per output
  int written_ = 0;
  size_t frameFiles_ = 0;
};
