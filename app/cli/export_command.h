// `penumbra export`: the pipeline headless on one scene; every stage output as EXR + PNG,
// and run.json with the scene, every parameter, the renderer, sizes and per-stage times.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/frame.h"
#include "core/pipeline.h"

struct ExportOptions {
  std::string scene = "cube";
  std::string outDirectory = "out";
  int width = 512, height = 512;
  std::vector<std::string> sets;  // "stage.key=value"
  std::uint32_t frameKey = 0;
  double time = 0;  // --time: seconds into the scene's animation (scene/animation.h)
  bool annotate = false;  // --annotate: PNGs carry a colour bar / legend and a caption
};

int runExport(const ExportOptions& options);

// Writes every output in `frame` (array textures: one file per layer) and run.json, as one
// transaction (app/io/output_path.h): `directory` then holds this export entirely, or, if
// anything fails, still the previous one. Returns the written paths. Used by export and
// by the window's "export all stages". `annotate`: each PNG gets the band of
// app/figures/annotate.h (the output's declared display: colour bar or legend; caption:
// scene, output, eye size and `keyParameters`); the EXRs stay raw.
std::vector<std::string> exportFrame(const std::string& directory, const Frame& frame,
                                     const Pipeline& pipeline, const std::string& renderer,
                                     bool annotate = false, const std::string& keyParameters = "");
