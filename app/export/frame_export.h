// A frame's outputs written to disk: every stage output as EXR + PNG, and run.json with the
// scene, every parameter, the renderer, sizes and per-stage times. Shared by `penumbra
// export` (app/cli/export_command.h) and the window's "Export all stages".
#pragma once
#include <string>
#include <vector>

#include "core/frame.h"
#include "core/pipeline.h"

// Writes every output in `frame` (array textures: one file per layer) and run.json, as one
// transaction (app/io/output_path.h): `directory` then holds this export entirely, or, if
// anything fails, still the previous one. Returns the written paths. Used by export and
// by the window's "export all stages". `annotate`: each PNG gets the band of
// app/figures/annotate.h (the output's declared display: colour bar or legend; caption:
// scene, output, eye size and `keyParameters`); the EXRs stay raw.
std::vector<std::string> exportFrame(const std::string& directory, const Frame& frame,
                                     const Pipeline& pipeline, const std::string& renderer,
                                     bool annotate = false, const std::string& keyParameters = "");
