// `auto`: model only what the scene needs (docs/accuracy.md). From the scene and the current view,
// on the CPU, before any GL work: the shadow-map resolution, the number of depth layers and
// the rays per pixel, each with the measurement that chose it.
//
// 1. Probes: points along the occluder edges (4 per edge of every stride-th triangle, the
//    stride chosen so that at most about 4 x kMaxProbes are cast), each followed along the
//    light's rays from the light centre past the occluder to the next surface (Embree, every
//    object, receivers included): that surface is where the penumbra of this edge falls.
// 2. Penumbra width at that receiver (parallel planes, as PCSS): w = light's smaller side x
//    (gap / distance from the light plane to the occluder), gaps measured along the light's
//    axis. Only probes whose receiver lies in the camera's view count (the view decides).
// 3. Rays: the filter cannot blur wider than the penumbra (filter.penumbra_scale), so where
//    the smallest penumbra is a few pixels wide the noise must go with more rays. Effective
//    samples = n^2 x the filter's pixel count pi sigma^2, sigma = min(2, 0.5 x width in
//    pixels), width the 2nd percentile of the probes; n is the smallest n >= 2 with at least
//    kEffectiveSamples (24), at most 8.
// 4. Resolution, weighing what the penumbrae need against what the map costs
//    (docs/decisions/043-auto-map-resolution.md):
//    each probe stands for a strip of penumbra (its width times its quarter edge's shadow,
//    in eye pixels). needed: the map on which 98% of that area spans kPenumbraTexels (6)
//    texels at its receiver's depth (resolution = 6 x 2 z tan(fov/2) / w). affordable: the
//    largest map whose build (N-buffer log2 R + 1 levels, light layers about 2: R^2 (log2 R + 3)
//    texel-levels)
//    costs no more than the trace would with these rays over every eye pixel
//    (kTexelLevelsPerPixelRay texel-levels per pixel and ray, measured on llvmpipe).
//    halfArea: the map on which the penumbrae holding half the area span 6 texels. The map
//    is min(needed, max(affordable, halfArea)): beyond the trace's cost only when the narrow
//    penumbrae are most of the shadow in view (a contact shadow), never beyond the need.
//    Multiples of 128 in [256 x max(1, tan(fov/2)), 2048]: a frustum widened past 90 degrees
//    (light.fov_degrees=auto) keeps its texels as narrow in the world as 256's at 90, since
//    every texel-sized offset (the normal offset, Eq 3.2's bias, the outline rounded to
//    texels) grows with the texel; where 2048 is not enough the reason says so (the limit
//    of depth maps, thesis §4.1, Atty 2006 §4.2). A probe's penumbra must also span
//    liftTexels / kLiftShiftFraction texels: the normal offset's part along the light's axis
//    (a lift towards the light), carried along a ray that reaches the receiver at angle a
//    from the axis, moves the receiver, and its penumbra, by the lift x tan a across the rays
//    (docs/decisions/150-auto-map-texels-at-a-wide-frustum.md). And the steep occluders
//    themselves (at least twice as deep along the light's axis as their image is wide: a
//    sheet a few degrees from edge-on to the light's centre): the map on which those holding
//    98% of the penumbra area (each probe weighs for its object) span kOccluderImageTexels
//    (12) across their narrowest image in the light's map (occluder_image.h). That need
//    stands above the cost cap: such an occluder is drawn by the few texel centres it
//    covers, and the rays from the light's other points cross each texel's error over its
//    whole depth, too bright or too dark in all of its shadow, not in a part of it
//    (docs/decisions/156-auto-map-from-the-occluders-images.md).
// Rasterizing the occluders rounds their outlines to texels, which shifts a penumbra by up
// to half a texel: with 6 texels per penumbra that is a bias of up to 8% across it.
// 5. Layers: the depth complexity along the probes' light rays (occluder surfaces crossed
//    between the light and the receiver). Two layers model one occluder exactly (near and far
//    bound it); with more than two crossings the space between occluders is solid for two
//    layers, and the third (the eye's depth, §3.4) frees what the eye sees of it. Two
//    surfaces can be two occluders too (two plates one above the other): the surfaces on
//    each in-view probe's ray are paired into solids by their facing, and where at least 5%
//    of those rays have free space of 2 texels or more between two occluders, three layers
//    (docs/decisions/116-auto-layers-from-separate-occluders.md). That pairing decides only
//    where no ray crosses more than two surfaces; elsewhere its rays are not cast.
// Cost per pose (an animated scene's frame: a new Embree scene of the posed triangles, the
// rays above; docs/decisions/140-auto-per-pose.md): the probes are shared out to the CPU's
// threads in a fixed order (the same answer whatever their number), and where the first
// 1/64 of the probes already count the most the depth-complexity walk counts (8), no other
// probe walks.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "gl/renderer_calibration.h"
#include "scene/light_frame.h"
#include "scene/scene.h"
#include "soft_shadow_maps/ssm/auto_ssm.h"

struct AutoSettings {
  int resolution = 512;
  int layers = 2;
  int raysPerSide = 2;
  // The measurements behind the choice.
  int probes = 0;                       // probes whose penumbra falls in view
  int neededResolution = 512;           // 98% of the penumbra area at 6 texels
  int affordableResolution = 512;       // the largest whose build costs <= the trace
  int halfAreaResolution = 512;         // half the penumbra area at 6 texels
  double smallestPenumbraWorld = 0;     // 2nd percentile, world units at the receiver
  double smallestPenumbraTexels = 0;    // the same in texels of the chosen map
  double smallestPenumbraPixels = 0;    // and in eye pixels
  double narrowestOccluderImage = 0;    // the occluders' image widths in the light's map,
                                        // 2nd percentile by penumbra area, fraction of the
                                        // map's side (occluder_image.h)
  int occluderImageResolution = 256;    // where that spans kOccluderImageTexels
  int depthComplexity = 0;              // most occluder surfaces on one probe's light ray
  int separateOccluderProbes = 0;       // in-view probes whose light ray has free space
                                        // between two occluders (step 5; 0 where the
                                        // depth complexity is above 2: not traced)
  std::vector<std::string> reasons;     // one sentence per choice
  std::string warning;                  // a steep occluder no map can show (step 4), or empty
  SsmResolutionNeed ssmNeed;            // ssm.resolution=auto's need (auto_ssm.h; the ssm stage caps it)
};

inline constexpr double kPenumbraTexels = 6.0;
// A steep occluder's image in the light's map (step 4: one at least kSteepDepthOverWidth
// times as deep along the light's axis as its image is wide) spans at least this many
// texels across its narrowest extent. On 36 sheets 1-24 degrees from edge-on, leaning
// either way about two axes (tests/accuracy/test_accuracy_hard_cases.cpp), an image 9.3
// texels wide left three of the four 10-degree sheets at 0.030 or over (filtered, mean
// |error| in shadow), 11.1 none; at 12 every sheet's error is at most 0.0294
// (docs/decisions/156-auto-map-from-the-occluders-images.md).
inline constexpr double kOccluderImageTexels = 12.0, kSteepDepthOverWidth = 2.0;
// The smallest map `auto` takes at a 90-degree frustum; a wider one (light.fov_degrees=auto)
// scales it by tan(fov / 2), so that its texels are no wider in the world (step 4).
inline constexpr double kMinResolution = 256.0;
// The normal offset's lift (light.normal_offset texel widths, its part along the light's
// axis) moves a penumbra across the ground where the light's rays reach it at a slant; the
// map is fine enough that it moves at most this fraction of the penumbra's width (step 4).
inline constexpr double kLiftShiftFraction = 0.05;
inline constexpr double kEffectiveSamples = 24.0;
inline constexpr int kMaxProbes = 20000;
// One ray for one eye pixel costs about this many texel-levels of map build. On llvmpipe,
// `penumbra bench --scene spheres --width 128 --height 96` (quiet machine): light layers +
// N-buffer 6.5e-6 ms per texel-level at map 512 (20.5 ms) and 2048 (383 ms); the trace
// 5.5e-5 ms per eye pixel and ray at 2x2, 4.0e-5 at 4x4, 6.3e-5 at 5x5 (ratios 6-10).
// The fallback: `auto` uses the value measured on its renderer (gl/renderer_calibration.h).
inline constexpr double kTexelLevelsPerPixelRay = kFallbackTexelLevelsPerPixelRay;

// The choice for this scene, light frame (Eq 3.1) and view (eye size in pixels). Cached:
// the same geometry (a hash of its positions, indices and flags), light, camera and size
// return the stored answer; the
// Embree scene is rebuilt only when the scene's geometry changes.
AutoSettings chooseAutoSettings(const Scene& scene, const LightFrame& light, int eyeWidth,
                                int eyeHeight, double normalOffsetTexels = 1.0);

// What chooseAutoSettings has done since the program started (every scene, every thread):
// for tests and measurements of its cost per pose.
struct AutoSettingsWork {
  std::uint64_t analyses = 0;   // analyses run (a new scene, light, camera or eye size)
  std::uint64_t bvhBuilds = 0;  // Embree scenes built (a new scene, or a new pose)
  std::uint64_t rays = 0;       // rays the analyses cast
};
AutoSettingsWork autoSettingsWork();

// What the `light` stage of `frame`'s pipeline chose in its last run (the defaults before it
// ran, or where the pipeline has no light stage); stages/shared_inputs/light/light.cpp.
struct Frame;
const AutoSettings& lightAutoSettings(const Frame& frame);
