// How wide each occluder's image is in the light's maps, and how deep the occluder is behind
// it: `auto`'s step 4 asks that a steep occluder whose shadow falls in view spans a dozen
// texels across its image (stages/shared_inputs/light/auto_settings.h,
// docs/decisions/156-auto-map-from-the-occluders-images.md).
//
// Why: the light layers rasterize an occluder at texel centres (thesis §3.3), so the edges of
// its image are placed to within half a texel, and each texel bounds the occluder over
// [near, far] across its whole footprint. For an occluder lying across the light's rays (a
// plate, a rod) that is a thin slab: the rays from the light's other points cross little of
// the error. For a steep one (a sheet a few degrees from edge-on to the light's centre) a
// texel's [near, far] spans a long stretch of depth, and a ray from a corner of the light
// crosses a texel's error over all of it: the error in its shadow grows with the depth over
// the image's width, and falls only with the image's width in texels.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "scene/light_frame.h"
#include "scene/scene.h"

// One occluder's image in the light's maps.
struct OccluderImage {
  // The narrowest width of its image (the minimum width of the convex hull of its vertices
  // seen from the projection point), as a fraction of the map's side along its wider axis:
  // times the map size, texels. 0 for an image that is a line (a sheet exactly edge-on).
  double width = std::numeric_limits<double>::infinity();
  // Its extent along the light's axis over that width in the world (at its nearest depth):
  // a sheet 4 degrees from edge-on about 14, a flat plate or a rod lying across the light's
  // rays about 1 or less.
  double depthOverWidth = 0;
};

// Per object of scene.objects. Receiver-only objects, empty meshes and objects with a vertex
// at or behind the projection point's plane (their image is unbounded) keep the defaults
// (infinitely wide, not deep).
std::vector<OccluderImage> occluderImages(const Scene& scene, const LightFrame& light);

// Step 4's measure over the in-view probes (`probeObjects`: the object each lies on;
// `probeAreas`: the penumbra area each stands for): the image width below which 2% of that
// area lies, counting only steep occluders (depthOverWidth >= steepDepthOverWidth; the others
// count as infinitely wide), and the steep occluders whose image is under a texel even at
// `largestMap` (a sheet exactly edge-on to the light's centre): no map shows them, so they are
// left out of the width and named.
struct SteepOccluders {
  double narrowestImage = std::numeric_limits<double>::infinity();
  std::vector<std::string> inNoMap;
};
SteepOccluders steepOccluders(const Scene& scene, const LightFrame& light,
                              const std::vector<unsigned>& probeObjects,
                              const std::vector<double>& probeAreas, double steepDepthOverWidth,
                              int largestMap);

// The minimum width of the convex hull of `points` (any order, repeats allowed): the
// smallest distance between two parallel lines enclosing them all. 0 for fewer than three
// points not on one line. For the tests.
double convexHullMinimumWidth(std::vector<glm::dvec2> points);
