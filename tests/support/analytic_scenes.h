// The accuracy suite (docs/accuracy.md): small scenes of plates and boxes whose visibility the
// analytic oracle (analytic_visibility.h) computes exactly, and the comparison of a pipeline
// output with it. Every scene: a receiver-only ground, convex occluders, one area light,
// a camera that sees the shadow.
#pragma once
#include <string>
#include <vector>

#include "scene/scene.h"
#include "support/analytic_visibility.h"

struct PipelineRun;

// Names: plate_mid, plate_contact, tilted_plate, box, stacked_plates, large_light,
// tiny_light, huge_ground.
std::vector<std::string> analyticSceneNames();
Scene makeAnalyticScene(const std::string& name);

// The exact visibility of every covered pixel of a run (GL order; -1 where no receiver),
// from its gbuffer.wsPosition / wsNormal (the point moved 1e-5 x max(1, |p|) along n).
std::vector<double> analyticImage(const PipelineRun& run);

struct AnalyticError {
  double meanAbsInShadow = 0;  // over pixels with exact visibility < 1 - 1e-9
  double maxAbs = 0;
  double meanSigned = 0;       // over the same pixels: > 0 too bright
  double meanInUmbra = 0;      // mean (method - exact) where exact visibility < 0.1: a leak
  size_t pixelsInShadow = 0, pixelsInUmbra = 0;
  size_t outOfRange = 0;       // NaN, Inf or outside [0, 1]
};

// `method`: one float per pixel (GL order), as many as `exact` (else std::invalid_argument).
// Pixels the light's map does not cover count like the others (the suite's scenes keep their
// shadows inside it).
AnalyticError compareWithAnalytic(const std::vector<float>& method,
                                  const std::vector<double>& exact);
