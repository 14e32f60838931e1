// `penumbra export`: the pipeline headless on one scene; every stage output as EXR + PNG,
// and run.json (app/export/frame_export.h writes them).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

struct ExportOptions {
  std::string scene = "cube";
  std::string outDirectory = "out";
  int width = 512, height = 512;
  std::vector<std::string> sets;  // "stage.key=value"
  std::uint32_t frameKey = 0;
  double time = 0;  // --time: seconds into the scene's animation (scene/animation.h)
  bool annotate = false;  // --annotate: PNGs carry a colour bar / legend and a caption
  // An animation (app/cli/video_command.h): --time-range A:B and --fps, the outputs per
  // frame (default composite.color), outputs composed side by side, no ffmpeg videos.
  std::string timeRange;
  double fps = 24;
  std::vector<std::string> outputs, sideBySide;
  bool framesOnly = false;
};

int runExport(const ExportOptions& options);
