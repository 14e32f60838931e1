#include "export/video_export.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "base/input_error.h"
#include "core/run_control.h"
#include "io/child_process.h"
#include "io/colormap.h"
#include "io/image_export.h"

namespace fs = std::filesystem;

namespace {

constexpr const char* kSideBySide = "side_by_side";

std::string frameName(int frame, const char* extension) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d.%s", frame, extension);
  return name;
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// ffmpeg failed: its own words (the last lines of its stderr), and the command.
std::string ffmpegFailure(const std::vector<std::string>& argv, const ChildResult& result) {
  std::string command;
  for (const std::string& arg : argv) command += (command.empty() ? "" : " ") + arg;
  std::string said = result.errorOutput;
  while (!said.empty() && (said.back() == '\n' || said.back() == '\r')) said.pop_back();
  if (said.size() > 2000) said = "..." + said.substr(said.size() - 2000);
  return "ffmpeg exited with status " + std::to_string(result.exitStatus) + ": " +
         (said.empty() ? "(it printed nothing)" : said) + "\n  command: " + command;
}

}  // namespace

// 1. The range.
int VideoRange::frames() const {
  const double exact = (end - start) * fps;
  return std::max(1, int(std::ceil(exact - 1e-9 * std::max(1.0, exact))));
}

double VideoRange::time(int frame) const { return start + double(frame) / fps; }

std::string videoRangeProblem(const VideoRange& range) {
  if (!std::isfinite(range.start) || !std::isfinite(range.end))
    return "the time range must be finite seconds";
  if (std::abs(range.start) > 1e9 || std::abs(range.end) > 1e9)
    return "the time range must lie within +-1e9 seconds";
  if (!(range.end > range.start))
    return "the time range must end after it starts (" + number(range.start) + ":" +
           number(range.end) + " is empty)";
  if (!std::isfinite(range.fps) || !(range.fps > 0) || range.fps > kMaxVideoFps)
    return "fps must be a number in (0, " + number(kMaxVideoFps) + "], not " + number(range.fps);
  const double frames = std::ceil((range.end - range.start) * range.fps);
  if (frames > kMaxVideoFrames)
    return "the time range " + number(range.start) + ":" + number(range.end) + " at " +
           number(range.fps) + " fps is " + number(frames) + " frames, more than " +
           std::to_string(kMaxVideoFrames) + "; shorten it or lower --fps";
  return "";
}

VideoRange parseVideoRange(const std::string& timeRange, double fps) {
  const size_t colon = timeRange.find(':');
  auto parse = [&](const std::string& text, double& value) {
    char* end = nullptr;
    value = std::strtod(text.c_str(), &end);
    return !text.empty() && *end == '\0';
  };
  VideoRange range;
  range.fps = fps;
  if (colon == std::string::npos || timeRange.find(':', colon + 1) != std::string::npos ||
      !parse(timeRange.substr(0, colon), range.start) || !parse(timeRange.substr(colon + 1), range.end))
    throw InputError("--time-range '" + printable(timeRange) + "': expected START:END in seconds, "
                     "e.g. 0:4");
  if (std::string problem = videoRangeProblem(range); !problem.empty()) {
    const bool fpsProblem = problem.rfind("fps", 0) == 0;
    throw InputError((fpsProblem ? "--fps: " : "--time-range '" + printable(timeRange) + "': ") + problem);
  }
  return range;
}

std::string ffmpegPath() { return findExecutable("ffmpeg"); }

std::string missingFfmpegMessage() {
  return "ffmpeg is not on PATH: the MP4 and GIF are made by it (Debian: apt-get install ffmpeg, "
         "or scripts/setup.sh); --frames-only writes the numbered frames without videos";
}

// 2. The request.
void checkVideoRequest(VideoRequest& request, const Pipeline& pipeline, const std::string& flag) {
  auto known = [&](const std::string& key) -> const Output* {
    for (const auto& stage : pipeline.stages())
      for (const Output& output : stage->outputs())
        if (stage->name() + "." + output.name == key) return &output;
    return nullptr;
  };
  auto check = [&](const std::string& key, const std::string& which) {
    const Output* output = known(key);
    if (!output)
      throw InputError(which + " '" + printable(key) + "' is not an output (stage.output; "
                       "`penumbra graph --markdown` lists them)");
    if (output->isBuffer())
      throw InputError(which + " '" + printable(key) + "' is a buffer handed between stages, "
                       "not an image");
  };
  if (request.outputs.empty()) throw InputError(flag + ": no output named");
  for (size_t i = 0; i < request.outputs.size(); ++i) {
    check(request.outputs[i], flag);
    if (std::find(request.outputs.begin(), request.outputs.begin() + long(i), request.outputs[i]) !=
        request.outputs.begin() + long(i))
      throw InputError(flag + " names '" + printable(request.outputs[i]) + "' twice");
  }
  if (request.sideBySide.size() == 1)
    throw InputError("--side-by-side needs two or more outputs (a,b,...), not one");
  for (const std::string& key : request.sideBySide) {
    check(key, "--side-by-side");
    if (std::count(request.sideBySide.begin(), request.sideBySide.end(), key) > 1)
      throw InputError("--side-by-side names '" + printable(key) + "' twice");
    if (std::find(request.outputs.begin(), request.outputs.end(), key) == request.outputs.end())
      request.outputs.push_back(key);
  }
}

// 3. The export.
VideoExport::VideoExport(const std::string& target, VideoRequest request, const Pipeline& pipeline)
    : request_(std::move(request)), pipeline_(pipeline) {
  if (std::string problem = videoRangeProblem(request_.range); !problem.empty()) throw InputError(problem);
  if (request_.encode && ffmpegPath().empty()) throw InputError(missingFfmpegMessage());
  checkOutputDirectory(target, "--out", "run.json");
  transaction_ = std::make_unique<DirectoryTransaction>(target, "run.json");
  for (const std::string& key : request_.outputs) fs::create_directory(transaction_->path() / key);
  if (!request_.sideBySide.empty()) fs::create_directory(transaction_->path() / kSideBySide);
  const int videos = int(request_.outputs.size()) + (request_.sideBySide.empty() ? 0 : 1);
  progress_ = std::make_unique<ProgressTask>("export video", frames() + (request_.encode ? 2 * videos : 0));
}

void VideoExport::writeFrame(int frame, const Frame& pipelineFrame) {
  if (frame != written_) throw std::logic_error("video frames must be written in order");
  const fs::path directory = transaction_->path();
  std::vector<std::vector<std::uint8_t>> images(request_.outputs.size());
  for (size_t i = 0; i < request_.outputs.size(); ++i) {
    const std::string& key = request_.outputs[i];
    if (!pipelineFrame.has(key))
      throw InputError("'" + key + "' was not written (is its stage disabled? --set " +
                       key.substr(0, key.find('.')) + ".enabled=true)");
    const GlTexture& texture = pipelineFrame.texture(key);
    if (texture.isArray())
      throw InputError("'" + key + "' is an array texture of " + std::to_string(texture.layers()) +
                       " levels; a video shows one image per frame: name a 2D output");
    const Output* declared = nullptr;
    for (const auto& stage : pipeline_.stages())
      for (const Output& output : stage->outputs())
        if (stage->name() + "." + output.name == key) declared = &output;
    const std::vector<float> values = texture.readFloats(0);
    if (frame == 0) {
      DisplayHint hint = declared->display;
      applyDataRange(hint, values, texture.channelCount());  // held for every frame
      hints_.push_back(hint);
      channels_.push_back(declared->channels);
      sizes_.emplace_back(texture.width(), texture.height());
    } else if (sizes_[i] != std::make_pair(texture.width(), texture.height())) {
      throw std::runtime_error("'" + key + "' changed size during the video");
    }
    writeExr(directory / key / frameName(frame, "exr"), values, texture.width(), texture.height(),
             channels_[i]);
    images[i] = displayRgb8(values, texture.width(), texture.height(), texture.channelCount(), hints_[i]);
    writePng(directory / key / frameName(frame, "png"), images[i], texture.width(), texture.height());
    frameFiles_ += 2;
  }
  if (!request_.sideBySide.empty()) {
    // Left to right in the order named; shorter images padded below with black.
    int width = 0, height = 0;
    std::vector<size_t> order;
    for (const std::string& key : request_.sideBySide) {
      const size_t i = size_t(std::find(request_.outputs.begin(), request_.outputs.end(), key) -
                              request_.outputs.begin());
      order.push_back(i);
      width += sizes_[i].first;
      height = std::max(height, sizes_[i].second);
    }
    std::vector<std::uint8_t> composed(size_t(width) * height * 3, 0);
    int x0 = 0;
    for (size_t i : order) {
      const auto [w, h] = sizes_[i];
      for (int y = 0; y < h; ++y)
        std::copy_n(&images[i][size_t(y) * w * 3], size_t(w) * 3, &composed[(size_t(y) * width + x0) * 3]);
      x0 += w;
    }
    writePng(directory / kSideBySide / frameName(frame, "png"), composed, width, height);
    width_ = width, height_ = height;
    ++frameFiles_;
  }
  ++written_;
  char detail[96];
  std::snprintf(detail, sizeof detail, "frame %d of %d (t = %.3f s)", frame + 1, frames(), time(frame));
  progress_->advance(detail);
}

void VideoExport::encode(const std::string& name, std::vector<std::string>& written) {
  const fs::path directory = transaction_->path();
  const std::string pattern = (directory / name / "frame_%04d.png").string();
  const std::string fps = number(request_.range.fps);
  const std::string count = std::to_string(frames());
  const std::vector<std::string> input = {"-nostdin", "-hide_banner", "-loglevel", "error", "-y",
                                          "-framerate", fps, "-start_number", "0", "-i", pattern,
                                          "-frames:v", count};
  // H.264 in yuv420p (what every player and slide program plays) needs an even width and
  // height: an odd edge gets one black row or column. The PNGs are sRGB; ffmpeg converts
  // them with the BT.601 matrix (its default), and the stream says so (smpte170m), so a
  // player converts back with the same matrix whatever the size.
  std::vector<std::string> mp4 = {ffmpegPath()};
  mp4.insert(mp4.end(), input.begin(), input.end());
  const fs::path mp4File = directory / (name + ".mp4");
  for (const char* arg : {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-preset", "medium",
                          "-crf", "16", "-pix_fmt", "yuv420p", "-colorspace", "smpte170m",
                          "-color_primaries", "bt709", "-color_trc", "iec61966-2-1", "-movflags", "+faststart"})
    mp4.emplace_back(arg);
  mp4.push_back(mp4File.string());
  // The GIF: one palette of 256 colours from every frame (palettegen), each pixel its
  // nearest palette colour (paletteuse without dithering, so a frame is a plain
  // quantisation of its PNG), looping forever.
  std::vector<std::string> gif = {ffmpegPath()};
  gif.insert(gif.end(), input.begin(), input.end());
  const fs::path gifFile = directory / (name + ".gif");
  for (const char* arg : {"-filter_complex", "[0:v]split[a][b];[a]palettegen=stats_mode=full[p];"
                                             "[b][p]paletteuse=dither=none",
                          "-loop", "0"})
    gif.emplace_back(arg);
  gif.push_back(gifFile.string());
  for (const auto& [argv, file] : {std::make_pair(mp4, mp4File), std::make_pair(gif, gifFile)}) {
    progress_->describe("encoding " + file.filename().string());
    const ChildResult result = runChild(argv);
    if (result.exitStatus != 0 || !fs::exists(file))
      throw std::runtime_error("encoding " + file.filename().string() + ": " + ffmpegFailure(argv, result));
    written.push_back((transaction_->target() / file.filename()).string());
    progress_->advance("encoded " + file.filename().string());
  }
}

std::vector<std::string> VideoExport::finish(nlohmann::json run, size_t& frameFiles) {
  if (written_ != frames())
    throw std::logic_error("video export finished after " + std::to_string(written_) + " of " +
                           std::to_string(frames()) + " frames");
  std::vector<std::string> written;
  if (request_.encode) {
    for (const std::string& key : request_.outputs) encode(key, written);
    if (!request_.sideBySide.empty()) encode(kSideBySide, written);
  }
  run["time_range"] = {request_.range.start, request_.range.end};
  run["fps"] = request_.range.fps;
  run["frames"] = frames();
  run["frame_times"] = "start + i / fps, i = 0 .. frames - 1 (the end is exclusive)";
  for (size_t i = 0; i < request_.outputs.size(); ++i) {
    const std::string& key = request_.outputs[i];
    nlohmann::json entry = {{"size", {sizes_[i].first, sizes_[i].second}},
                            {"channels", channels_[i]},
                            {"frames", key + "/frame_NNNN.exr|png"},
                            {"png_display", {{"channel", hints_[i].channel},
                                             {"black", hints_[i].black},
                                             {"white", hints_[i].white}}}};
    if (request_.encode) entry["videos"] = {key + ".mp4", key + ".gif"};
    run["video_outputs"][key] = entry;
  }
  if (!request_.sideBySide.empty()) {
    run["side_by_side"] = {{"outputs", request_.sideBySide},
                           {"size", {width_, height_}},
                           {"frames", std::string(kSideBySide) + "/frame_NNNN.png"}};
    if (request_.encode) run["side_by_side"]["videos"] = {std::string(kSideBySide) + ".mp4",
                                                          std::string(kSideBySide) + ".gif"};
  }
  if (request_.encode) run["encoder"] = {{"mp4", "ffmpeg libx264 yuv420p crf 16, even size"},
                                         {"gif", "ffmpeg palettegen (all frames) + paletteuse, no dither"}};
  for (const auto& stage : pipeline_.stages()) {
    nlohmann::json params = nlohmann::json::object();
    for (const Param& param : stage->params()) params[param.key] = param.toString();
    run["parameters"][stage->name()] = params;
  }
  writeTextFile(transaction_->path() / "run.json", run.dump(2) + "\n");
  written.push_back((transaction_->target() / "run.json").string());
  throwIfRunCancelled("before the video export's commit");
  transaction_->commit();
  frameFiles = frameFiles_;
  return written;
}
