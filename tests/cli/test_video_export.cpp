// `penumbra export --time-range A:B --fps F` (app/export/video_export.h, decision 130): the
// numbered frames, the MP4 and the GIF per output and side by side, checked with ffprobe
// and ffmpeg as an independent decoder; bad ranges and a missing ffmpeg are exit 2 before
// any work; Ctrl-C and a kill leave nothing half-written.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/command.h"
#include "support/temp_directory.h"

namespace fs = std::filesystem;

namespace {

bool haveFfmpeg() { return runShell("command -v ffmpeg && command -v ffprobe").exitCode == 0; }

std::vector<unsigned char> readRgb(const fs::path& png, int& width, int& height) {
  auto input = OIIO::ImageInput::open(png.string());
  if (!input) return {};
  const OIIO::ImageSpec& spec = input->spec();
  width = spec.width, height = spec.height;
  std::vector<unsigned char> pixels(size_t(width) * height * 3);
  input->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, pixels.data());
  input->close();
  return pixels;
}

// Frame `index` of a video decoded by ffmpeg to rgb24 bytes (w x h x 3, top row first).
std::vector<unsigned char> decodeFrame(const fs::path& video, int index, const fs::path& scratch) {
  const fs::path raw = scratch / (video.filename().string() + "." + std::to_string(index) + ".rgb");
  const CommandResult result = runShell("ffmpeg -v error -nostdin -y -i " + video.string() +
                                        " -vf 'select=eq(n\\," + std::to_string(index) +
                                        ")' -frames:v 1 -f rawvideo -pix_fmt rgb24 " + raw.string());
  if (result.exitCode != 0) ADD_FAILURE() << result.output;
  std::ifstream in(raw, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

nlohmann::json probe(const fs::path& video) {
  const CommandResult result = runShell("ffprobe -v error -count_frames -select_streams v:0 "
                                        "-show_entries stream=codec_name,pix_fmt,width,height,nb_read_frames "
                                        "-of json " + video.string() + " 2>/dev/null");
  EXPECT_EQ(result.exitCode, 0) << result.output;
  return nlohmann::json::parse(result.output)["streams"][0];
}

struct Difference {
  double meanAbs = 0;  // over every byte
  int maxAbs = 0;
  double psnr = 0;     // dB
};

Difference compare(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b) {
  Difference d;
  if (a.size() != b.size() || a.empty()) {
    ADD_FAILURE() << "sizes differ: " << a.size() << " vs " << b.size();
    return d;
  }
  double squared = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    const int delta = std::abs(int(a[i]) - int(b[i]));
    d.meanAbs += delta;
    squared += double(delta) * delta;
    d.maxAbs = std::max(d.maxAbs, delta);
  }
  d.meanAbs /= double(a.size());
  const double mse = squared / double(a.size());
  d.psnr = mse > 0 ? 10 * std::log10(255.0 * 255.0 / mse) : 99;
  return d;
}

size_t count(const fs::path& directory, const std::string& extension) {
  size_t n = 0;
  for (const auto& entry : fs::directory_iterator(directory)) n += entry.path().extension() == extension;
  return n;
}

}  // namespace

// 12 frames of the light sweep (the penumbra widens), the final image and the hard shadow's
// visibility, and the two side by side.
TEST(VideoExport, Mp4AndGifHoldEveryFrameAndStartWithFrameZero) {
  if (!haveFfmpeg()) GTEST_SKIP() << "ffmpeg / ffprobe not installed (scripts/setup.sh installs them)";
  const TempDirectory dir("penumbra_video");
  const fs::path out = dir.path() / "video";
  const CommandResult result = runPenumbra(
      "export --scene light_sweep --time-range 0:1 --fps 12 --width 64 --height 48 --side-by-side "
      "composite.color,hard_shadow.visibility --out " + out.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  for (const std::string output : {"composite.color", "hard_shadow.visibility"}) {
    EXPECT_EQ(count(out / output, ".png"), 12u) << output;
    EXPECT_EQ(count(out / output, ".exr"), 12u) << output;
  }
  EXPECT_EQ(count(out / "side_by_side", ".png"), 12u);
  const nlohmann::json run = nlohmann::json::parse(std::ifstream(out / "run.json"));
  EXPECT_EQ(run["frames"].get<int>(), 12);
  EXPECT_EQ(run["fps"].get<double>(), 12.0);

  for (const std::string name : {"composite.color", "side_by_side"}) {
    const fs::path mp4 = out / (name + ".mp4"), gif = out / (name + ".gif");
    const nlohmann::json video = probe(mp4);
    EXPECT_EQ(video["codec_name"], "h264") << name;
    EXPECT_EQ(video["pix_fmt"], "yuv420p") << name;
    EXPECT_EQ(video["nb_read_frames"], "12") << name;
    EXPECT_EQ(probe(gif)["nb_read_frames"], "12") << name;
    int width = 0, height = 0;
    const std::vector<unsigned char> first = readRgb(out / name / "frame_0000.png", width, height);
    const std::vector<unsigned char> last = readRgb(out / name / "frame_0011.png", width, height);
    EXPECT_EQ(video["width"].get<int>(), width);
    EXPECT_EQ(video["height"].get<int>(), height);
    // The MP4's first frame against the PNG of frame 0. H.264 at crf 16 in yuv420p keeps
    // luma nearly exact but halves chroma in both directions, so colour edges (the
    // shadow's border on the coloured floor) differ by more: asserted as PSNR >= 30 dB and
    // a mean error under 2 of 255. And it must be frame 0: closer to it than to frame 11.
    const std::vector<unsigned char> decoded = decodeFrame(mp4, 0, dir.path());
    const Difference toFirst = compare(decoded, first), toLast = compare(decoded, last);
    std::printf("%s.mp4 frame 0: PSNR %.1f dB, mean |d| %.3f, max |d| %d; against frame 11: "
                "PSNR %.1f dB, mean |d| %.3f\n", name.c_str(), toFirst.psnr, toFirst.meanAbs,
                toFirst.maxAbs, toLast.psnr, toLast.meanAbs);
    EXPECT_GE(toFirst.psnr, 30.0) << name;
    EXPECT_LT(toFirst.meanAbs, 2.0) << name;
    EXPECT_LT(toFirst.meanAbs, toLast.meanAbs) << name;
    // The GIF's first frame: each pixel is its colour's nearest entry of one 256-colour
    // palette made over all frames, no dithering; the error is the palette's quantisation
    // only, small here (12 frames of 64x48 hold few more colours than the palette: measured
    // 77.8 dB, max 1 of 255): asserted as PSNR >= 45 dB (a wrong frame, a flip or a
    // dithered palette fail it), and closer to frame 0 than to frame 11.
    const std::vector<unsigned char> gifFirst = decodeFrame(gif, 0, dir.path());
    const Difference gifToFirst = compare(gifFirst, first), gifToLast = compare(gifFirst, last);
    std::printf("%s.gif frame 0: PSNR %.1f dB, mean |d| %.3f, max |d| %d; against frame 11: "
                "mean |d| %.3f\n", name.c_str(), gifToFirst.psnr, gifToFirst.meanAbs,
                gifToFirst.maxAbs, gifToLast.meanAbs);
    EXPECT_GE(gifToFirst.psnr, 45.0) << name;
    EXPECT_LT(gifToFirst.meanAbs, gifToLast.meanAbs) << name;
  }
}

// Odd sizes: H.264 in yuv420p needs even ones; the MP4 gets one black column and row.
TEST(VideoExport, OddSizeIsPaddedToEven) {
  if (!haveFfmpeg()) GTEST_SKIP() << "ffmpeg / ffprobe not installed";
  const TempDirectory dir("penumbra_video_odd");
  const fs::path out = dir.path() / "odd";
  const CommandResult result = runPenumbra("export --scene toys --time-range 0:0.25 --fps 8 --width 33 "
                                           "--height 21 --out " + out.string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const nlohmann::json video = probe(out / "composite.color.mp4");
  EXPECT_EQ(video["width"].get<int>(), 34);
  EXPECT_EQ(video["height"].get<int>(), 22);
  EXPECT_EQ(video["nb_read_frames"], "2");
  EXPECT_EQ(probe(out / "composite.color.gif")["width"].get<int>(), 33);
}

TEST(VideoExport, BadRangesAndFpsAreExitTwoBeforeAnyWork) {
  const TempDirectory dir("penumbra_video_bad");
  const fs::path out = dir.path() / "never";
  const std::pair<std::string, std::string> cases[] = {
      {"--time-range 4:4", "must end after it starts"},
      {"--time-range 4:1", "must end after it starts"},
      {"--time-range 0:nan", "finite"},
      {"--time-range=-inf:1", "finite"},
      {"--time-range 0-4", "expected START:END"},
      {"--time-range 0:4:5", "expected START:END"},
      {"--time-range 0:4 --fps 0", "--fps: fps must be a number in (0, 240]"},
      {"--time-range 0:4 --fps -24", "--fps"},
      {"--time-range 0:4 --fps 241", "--fps"},
      {"--time-range 0:4 --fps nan", "--fps"},
      {"--time-range 0:100 --fps 240", "more than 10000"},
      {"--time-range 0:1 --outputs composite.nothing", "is not an output"},
      {"--time-range 0:1 --side-by-side composite.color", "two or more"},
  };
  for (const auto& [flags, message] : cases) {
    const CommandResult result = runPenumbra("export --scene light_sweep --width 16 --height 16 " +
                                             flags + " --out " + out.string());
    EXPECT_EQ(result.exitCode, 2) << flags << "\n" << result.output;
    EXPECT_NE(result.output.find(message), std::string::npos) << flags << "\n" << result.output;
    EXPECT_EQ(result.output.find("posed at"), std::string::npos) << flags << ": work began";
    EXPECT_FALSE(fs::exists(out)) << flags;
  }
  // --fps without --time-range is a usage error too.
  EXPECT_EQ(runPenumbra("export --fps 24 --out " + out.string()).exitCode, 2);
}

// Chosen: without ffmpeg the export is refused before any work (exit 2, naming the fix),
// unless --frames-only asks for the frames alone.
TEST(VideoExport, WithoutFfmpegExitTwoOrFramesOnly) {
  const TempDirectory dir("penumbra_video_noffmpeg");
  const fs::path out = dir.path() / "frames";
  const std::string command = "PATH=/nonexistent " + penumbraBinary() +
                              " export --scene toys --time-range 0:0.5 --fps 4 --width 16 --height 16 --out " +
                              out.string();
  const CommandResult refused = runShell(command);
  EXPECT_EQ(refused.exitCode, 2) << refused.output;
  EXPECT_NE(refused.output.find("ffmpeg is not on PATH"), std::string::npos) << refused.output;
  EXPECT_NE(refused.output.find("--frames-only"), std::string::npos) << refused.output;
  EXPECT_FALSE(fs::exists(out));
  const CommandResult frames = runShell(command + " --frames-only");
  ASSERT_EQ(frames.exitCode, 0) << frames.output;
  EXPECT_EQ(count(out / "composite.color", ".png"), 2u);
  EXPECT_FALSE(fs::exists(out / "composite.color.mp4"));
}

// A previous export in place; a second one stopped by SIGTERM (handled as Ctrl-C is; a
// shell starts `&` commands with SIGINT ignored, so the test cannot send that one) and one
// killed (SIGKILL) halfway: the target still holds the first, whole; the stopped one leaves
// no temporary, the kill's is removed by the next export of the same directory.
TEST(VideoExport, InterruptedOrKilledExportLeavesThePreviousWhole) {
  const TempDirectory dir("penumbra_video_kill");
  const fs::path out = dir.path() / "anim";
  const std::string base = penumbraBinary() + " export --scene toys --width 48 --height 32 --frames-only --out " +
                           out.string();
  ASSERT_EQ(runShell(base + " --time-range 0:0.5 --fps 4").exitCode, 0);
  ASSERT_EQ(count(out / "composite.color", ".png"), 2u);
  for (const std::string signal : {"TERM", "KILL"}) {
    // Started in the background; the signal once its temporary directory holds 3 frames.
    const std::string script =
        base + " --time-range 0:10 --fps 24 2>&1 & pid=$!; "
        "for i in $(seq 1 600); do [ -e " + dir.path().string() + "/.anim.partial-$pid/composite.color/frame_0002.png ] && break; sleep 0.1; done; "
        "kill -" + signal + " $pid; wait $pid; echo \"exit=$?\"";
    const CommandResult result = runShell(script);
    if (signal == "TERM") {
      EXPECT_NE(result.output.find("exit=1"), std::string::npos) << result.output;
      EXPECT_NE(result.output.find("stopped"), std::string::npos) << result.output;
      EXPECT_NE(result.output.find("nothing was written"), std::string::npos) << result.output;
    } else {
      EXPECT_NE(result.output.find("exit=137"), std::string::npos) << result.output;
    }
    EXPECT_EQ(count(out / "composite.color", ".png"), 2u) << signal << ": the previous export changed";
    const nlohmann::json run = nlohmann::json::parse(std::ifstream(out / "run.json"));
    EXPECT_EQ(run["frames"].get<int>(), 2) << signal;
    size_t temporaries = 0;
    for (const auto& entry : fs::directory_iterator(dir.path()))
      temporaries += entry.path().filename().string().rfind(".anim.partial-", 0) == 0;
    EXPECT_EQ(temporaries, signal == "TERM" ? 0u : 1u) << signal;
  }
  ASSERT_EQ(runShell(base + " --time-range 0:0.75 --fps 4").exitCode, 0);
  EXPECT_EQ(count(out / "composite.color", ".png"), 3u);
  for (const auto& entry : fs::directory_iterator(dir.path()))
    EXPECT_EQ(entry.path().filename(), "anim") << "left behind: " << entry.path();
}

// Not a terminal (a pipe here): plain lines, at most one per 10 %, then one "done" line.
TEST(VideoExport, ProgressIsPlainLinesWhenNotATerminal) {
  const TempDirectory dir("penumbra_video_progress");
  const CommandResult result = runShell(
      "PENUMBRA_PROGRESS_AFTER=0 " + penumbraBinary() + " export --scene toys --width 16 --height 16 "
      "--frames-only --time-range 0:1 --fps 20 --out " + (dir.path() / "p").string());
  ASSERT_EQ(result.exitCode, 0) << result.output;
  size_t lines = 0;
  for (size_t at = 0; (at = result.output.find("penumbra export: ", at)) != std::string::npos; ++at)
    lines += result.output.compare(at + 17, 1, " ") == 0 || std::isdigit(result.output[at + 17]);
  EXPECT_GE(lines, 5u) << result.output;
  EXPECT_LE(lines, 11u) << result.output;
  EXPECT_NE(result.output.find("penumbra export: done: 20 of 20 steps (100%)"), std::string::npos) << result.output;
  EXPECT_EQ(result.output.find('\r'), std::string::npos) << "a carriage return outside a terminal";
}
