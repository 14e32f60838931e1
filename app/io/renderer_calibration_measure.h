// The calibration run behind `auto` per renderer (renderer_calibration.h): a few frames of the
// built-in `spheres` scene at 256 x 192, each stage timed as `penumbra bench` times it
// (GL_TIME_ELAPSED on a GPU, glFinish + steady clock on llvmpipe), the median of 3 frames after
// a warm-up of each of four configurations:
//   A  map 512,  N-buffer,       2x2 rays    B  map 1024, N-buffer, 2x2 rays
//   C  map 512,  N-buffer,       4x4 rays    D  map 512,  min-max,  2x2 rays
// map build per texel-level  = (light_layers + nbuffer)(B - A) / (W(1024) - W(512)),
//                              W(R) = R^2 (log2 R + 3) (auto_settings.cpp mapBuildWork);
// trace per pixel and ray    = trace(C - A) / (pixels x (16 - 4));
// texelLevelsPerPixelRay     = trace per pixel-ray / build per texel-level;
// N-buffer's extra build     = (nbuffer(A) - minmax(D)) / the N-buffer's texel-levels at 512;
// min-max's extra eye cost   = (classify + trace)(D - A) / pixels;
// nbufferTexelLevelsPerEyePixel = extra eye cost / extra build per texel-level.
// A difference that is not positive (the two sides equal within the timer's noise) keeps that
// crossover's constant, said in the notes. Values are rounded to two significant digits.
// Needs a current GL context; leaves GL state as a pipeline run does.
#pragma once
#include "gl/renderer_calibration.h"

RendererCalibration measureRendererCalibration();

// Resolves the calibration of the current context (calibrationRequest(override)), makes it the
// active one and prints what was done as "penumbra <command>: ..." on stderr. Returns 0, 2 for
// a pinned file that cannot be used (bad input), 1 when the measurement failed.
int applyRendererCalibration(const std::string& command, const std::string& override = "");
