// What `penumbra bench` measures: setups (what the reference depends on: the scene as
// modified by a sweep, the eye size) each with configurations (what only the method
// depends on: `--set` assignments). Presets and `--sweep` build them.
//
// The methods come from the graph (Pipeline::methods(), role kRoleShadowMethod). The Monte
// Carlo method (stages `trace` and `filter`) has its own configuration lists (search type,
// layers, rays); every other method is measured with its declared defaults at the preset's
// shadow-map sizes, so a new method appears without an edit here.
//
// Presets:
//   default           every other method at map 512, 128, 1024; Monte Carlo linear,
//                     linear_binary (2 and 3 layers), hierarchical at 1, 4, 9, 16 rays;
//                     filter off; forward; map 128..1024; `auto` (map, layers, rays; issue
//                     12) (one setup, small enough for a few minutes on llvmpipe)
//   minimal           every other method and hierarchical 2x2 (for sweeps and CI)
//   thesis-table-4.1  the thesis's table shapes (Tables 4.1-4.4): search type x rays x
//                     deferred against shadow-map size 256/512/1024 at the main eye size,
//                     and against three eye sizes at map 512 (the thesis's 800x600,
//                     1024x768, 1280x1024 scaled by width/1024; default width 512); every
//                     other method at map 512 in the main setup
//   atty-4.2          the sweeps of Atty et al. 2006 §4.2 with their metric (mean |error|
//                     over pixels in shadow): shadow-map size; light size; occluder moved
//                     laterally; occluder moved from the receiver to the light (map 128,
//                     as theirs); every method in each, a method with passes (ssm) at each
//                     of them, as Atty et al. measure one and two passes; the error over
//                     the receiver-only objects' pixels (error.pixels=receivers), as theirs
//
// A method whose stage has maps of its own (an Int parameter `resolution`, e.g. ssm) gets
// <method>.resolution = the map size beside light.resolution, so Fig. 17's x axis is its map.

// --sweep KEY=v1,v2,...: KEY is a stage parameter (every configuration is repeated for each
// value) or one of the setup axes scene.light_scale (light width and height x v),
// scene.lateral (occluders' centre at v light widths from the light's axis, along the
// light's right), scene.vertical (0: occluders touch the receivers, 1: they touch the
// light), eye.size (WxH).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "scene/scene.h"

class Pipeline;

struct BenchConfig {
  std::string label;               // "hierarchical 2L 2x2 map 512", "<method> map 128"
  std::string method;              // the method's stage (Pipeline::methods())
  std::string family;              // plot series: "hierarchical 2L", or the method's name
  std::vector<std::string> sets;   // stage.key=value on top of the defaults
  // > 0: the reference as a method at m x m light samples (method "reference"; no stage of
  // the graph is its visibility: app/bench/bench_reference.h).
  int referenceSamples = 0;
  bool rebuildBvh = false;         // its BVH built anew every timed frame (a moving scene)
};

struct BenchSetup {
  std::string label;        // "cube 256x256", "cube 256x256 light_scale=0.5"
  std::string axis;         // the sweep axis this setup belongs to ("" for none)
  double axisValue = 0;
  Scene scene;
  int width = 256, height = 256;
  std::vector<BenchConfig> configs;
  // An animated setup (preset animated): `scene` is posed at loopTimes[0] (its error frame and
  // its reference); `rest` is the scene with its animation, posed anew at every loop time.
  std::shared_ptr<const Scene> rest;
  std::vector<double> loopTimes;  // seconds, one per timed frame of the loop
  double fps = 0, cycle = 0;      // frames per second; one cycle's duration
  std::vector<double> poseMs;     // measured: posing and uploading each loop frame (ms)
  bool animated() const { return rest && !loopTimes.empty(); }
};

struct BenchPlanOptions {
  std::string preset;               // "" = default
  std::vector<std::string> sweeps;  // "stage.key=v1,v2" or "scene.light_scale=..." ...
  int width = 0, height = 0;        // 0: the preset's default
  double fps = 12;                  // animated: frames per second over one cycle
  int loopFrames = 0;               // animated: only the first N of them (0: the whole cycle)
  double time = 0;                  // animated: the loop's first time
};

// The methods and their parameters come from `pipeline` (read, not changed). `scene` is
// posed for every preset but animated, which needs its animation (at rest). Throws
// std::invalid_argument with a message naming the valid presets / keys.
std::vector<BenchSetup> makeBenchPlan(const Scene& scene, const BenchPlanOptions& options,
                                      const Pipeline& pipeline);
std::vector<std::string> benchPresetNames();

// The setup modifiers (public for tests).
void scaleLight(Scene& scene, double factor);
void placeOccludersLaterally(Scene& scene, double lightWidths);
void placeOccludersVertically(Scene& scene, double fromReceiverToLight);
// The reference as a method at m x m samples ("reference 4x4", "reference 32x32 BVH rebuilt").
BenchConfig referenceConfig(int samples, bool rebuildBvh = false);
// The times of the loop: start + i / fps for i < round(cycle x fps) (at least one), the
// first `limit` of them when limit > 0.
std::vector<double> loopTimes(double start, double cycle, double fps, int limit);
