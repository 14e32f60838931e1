// penumbra: a step-by-step visualizer of Monte Carlo soft shadows (Curtis & Olano 2009).
// Subcommands (docs/design.md#program). One handler for every command: bad input (InputError:
// flags, scenes, parameter values, output paths) prints what is wrong and exits with status 2; any
// other exception is an internal failure, printed, exit status 1. Nothing escapes.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <new>

#include "bench/bench_report.h"
#include "bench/bench_raster4d.h"
#include "bench/bench_hierarchy.h"
#include "bench/bench_compare.h"
#include "bench/bench_stages.h"
#include "bench/bench_temporal.h"
#include "cli/calibrate_command.h"
#include "cli/export_command.h"
#include "cli/hash_command.h"
#include "cli/hash_stats_command.h"
#include "cli/progress_line.h"
#include "gl/hash_kind.h"
#include "io/shader_dump.h"
#include "cli/trace_command.h"
#include "base/input_error.h"
#include "core/pipeline.h"
#include "core/run_control.h"
#include "io/output_path.h"
#include "core/stage_table.h"
#include "window/window_app.h"

namespace {

// A positive finite number of seconds (CLI::PositiveNumber prints DBL_MAX in full).
std::string positiveSeconds(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end || !std::isfinite(value) || value <= 0 || value > 1e7)
    return "'" + printable(text) + "' is not a number of seconds in (0, 1e7]";
  return "";
}

// Every command, under the one handler.
int runCommand(const std::string& command, const std::function<int()>& run) {
  const std::string prefix = "penumbra" + (command.empty() ? "" : " " + command) + ": ";
  try {
    return run();
  } catch (const InputError& error) {
    std::fprintf(stderr, "%s%s\n", prefix.c_str(), error.what());
    return 2;
  } catch (const RunCancelled& error) {
    std::fprintf(stderr, "%sstopped: %s; nothing was written\n", prefix.c_str(), error.what());
    return 1;
  } catch (const WriteError& error) {  // the file system said no (io/output_path.h)
    std::fprintf(stderr, "%s%s\n", prefix.c_str(), error.what());
    return 1;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "%sout of memory\n", prefix.c_str());
    return 1;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "%sinternal error: %s\n", prefix.c_str(), error.what());
    return 1;
  } catch (...) {
    std::fprintf(stderr, "%sinternal error (unknown exception)\n", prefix.c_str());
    return 1;
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"penumbra - a step-by-step visualizer of real-time soft shadows"};
  app.require_subcommand(0, 1);

  WindowOptions window;
  app.add_option("--scene", window.scene, "built-in scene (cube, plate, spheres, engine, dragon; animated: "
                                          "dragon_turntable, light_sweep, toys, slow_slide) or a .json/.gltf/.glb file")->capture_default_str();
  app.add_option("--set", window.sets, "stage.key=value, repeatable");
  app.add_option("--screenshot", window.screenshot, "save the window to this PNG and exit");
  app.add_option("--frames", window.frames, "frames to render before --screenshot")
      ->check(CLI::Range(1, 100000))->capture_default_str();
  app.add_option("--width", window.width, "window width")->check(CLI::Range(320, 8192));
  app.add_option("--height", window.height, "window height")->check(CLI::Range(240, 8192));
  app.add_option("--config", window.config, "settings JSON to start from (saved by the window)");
  app.add_option("--script", window.script, "JSON list of UI actions to run, then exit");
  app.add_option("--export", window.exportDirectory, "directory for the script's relative exports");

  WindowOptions lesson;  // a lesson is a script with texts (app/window/script/ui_script.h, lessons/*.json)
  CLI::App* lessonCommand = app.add_subcommand("lesson", "play a lesson in the window; with "
                                                         "--export, run it through and write its figures");
  lessonCommand->add_option("file", lesson.script, "lesson JSON (e.g. lessons/fig_3_2_progression.json)")
      ->required()->check(CLI::ExistingFile);
  lessonCommand->add_option("--export", lesson.exportDirectory,
                            "write the figures, their sheet (figure_sheet.png/.pdf) and lesson.md "
                            "here and exit (played without it, they go to penumbra_exports/<lesson>)");
  lessonCommand->add_option("--scene", lesson.scene, "scene to start from")->capture_default_str();
  lessonCommand->add_option("--screenshot", lesson.screenshot, "save the window after --frames and exit");
  lessonCommand->add_option("--frames", lesson.frames, "frames before --screenshot")->check(CLI::Range(1, 100000));

  ExportOptions exporting;
  CLI::App* exportCommand = app.add_subcommand("export", "run the pipeline headless and write "
                                                         "every stage output (EXR + PNG) and run.json");
  exportCommand->add_option("--scene", exporting.scene, "built-in scene or scene file")
      ->capture_default_str();
  exportCommand->add_option("--out", exporting.outDirectory, "output directory")
      ->capture_default_str();
  exportCommand->add_option("--width", exporting.width, "eye image width")
      ->check(CLI::Range(1, 8192))->capture_default_str();
  exportCommand->add_option("--height", exporting.height, "eye image height")
      ->check(CLI::Range(1, 8192))->capture_default_str();
  exportCommand->add_option("--set", exporting.sets, "stage.key=value, repeatable");
  exportCommand->add_option("--frame-key", exporting.frameKey, "hash key of the frame")
      ->capture_default_str();
  exportCommand->add_option("--time", exporting.time, "seconds into the scene's animation "
                            "(the scene posed at that time; static scenes ignore it)")
      ->capture_default_str();
  exportCommand->add_flag("--annotate", exporting.annotate,
                          "PNGs carry a colour bar (range, channel) or legend and a caption "
                          "line below the image; the EXRs stay raw");
  // An animation for slides (app/cli/video_command.h, README "Video export").
  CLI::Option* timeRangeOption = exportCommand->add_option(
      "--time-range", exporting.timeRange, "START:END seconds (end exclusive): every frame's "
      "outputs as numbered EXR + PNG, and an MP4 and a GIF per output through ffmpeg");
  exportCommand->add_option("--fps", exporting.fps, "frames per second of --time-range, in (0, 240]")
      ->needs(timeRangeOption)->capture_default_str();
  exportCommand->add_option("--outputs", exporting.outputs, "stage.output,... written per frame "
                            "(default composite.color)")->needs(timeRangeOption)->delimiter(',');
  exportCommand->add_option("--side-by-side", exporting.sideBySide, "stage.output,... composed "
                            "left to right into one more video")->needs(timeRangeOption)->delimiter(',');
  exportCommand->add_flag("--frames-only", exporting.framesOnly, "the numbered frames without "
                          "the MP4s and GIFs (no ffmpeg needed)")->needs(timeRangeOption);

  TraceOptions tracing;
  CLI::App* traceCommand = app.add_subcommand("trace", "record every step of every ray at one "
                                                       "pixel, as JSON");
  traceCommand->add_option("--scene", tracing.scene, "built-in scene or scene file")
      ->capture_default_str();
  traceCommand->add_option("--pixel", tracing.pixel, "X,Y in image coordinates (row 0 on top)")
      ->required();
  traceCommand->add_option("--out", tracing.out, "JSON file (default: standard output)");
  traceCommand->add_option("--width", tracing.width, "eye image width")
      ->check(CLI::Range(1, 8192))->capture_default_str();
  traceCommand->add_option("--height", tracing.height, "eye image height")
      ->check(CLI::Range(1, 8192))->capture_default_str();
  traceCommand->add_option("--set", tracing.sets, "stage.key=value, repeatable");
  traceCommand->add_option("--time", tracing.time, "seconds into the scene's animation")
      ->capture_default_str();

  HashOptions hashing;
  CLI::App* hashCommand = app.add_subcommand("hash", "raw little-endian uint32 stream of a hash "
                                                     "on the inputs 1, 2, ... (dieharder -g 200)");
  hashCommand->add_option("--hash", hashing.hash, hashKindList())->capture_default_str();
  hashCommand->add_option("--count", hashing.count, "number of hashes (16 bytes each)")
      ->check(CLI::Range(std::uint64_t(1), std::uint64_t(4294967295u)))->capture_default_str();
  hashCommand->add_option("--key", hashing.key, "key XORed into every seed")->capture_default_str();

  HashStatsOptions hashStats;
  CLI::App* hashStatsCommand = app.add_subcommand(
      "hash-stats", "DIEHARD-like statistics of the hashes on the GPU (table, JSON, images); "
                    "--dieharder runs the real battery");
  hashStatsCommand->add_option("--hash", hashStats.hash, "all, " + hashKindList())->capture_default_str();
  hashStatsCommand->add_option("--pattern", hashStats.pattern, "all, linear, pixels, morton, frames")
      ->capture_default_str();
  hashStatsCommand->add_option("--count", hashStats.count, "samples per key, 1024 .. 2^24")
      ->capture_default_str();
  hashStatsCommand->add_option("--keys", hashStats.keys, "keys K (KS test of the K p-values)")
      ->capture_default_str();
  hashStatsCommand->add_option("--key", hashStats.key, "first key")->capture_default_str();
  hashStatsCommand->add_option("--out", hashStats.out, "directory for hash_stats.md/.json and images");
  hashStatsCommand->add_flag("--dieharder", hashStats.dieharder,
                             "also run penumbra hash | dieharder -g 200 on the DIEHARD tests");

  BenchStagesOptions benching;
  CLI::App* benchStagesCommand = app.add_subcommand(
      "bench-stages", "per-stage milliseconds, fetches per ray and classification savings on "
                      "cube and engine (writes a Markdown table)");
  benchStagesCommand->add_option("--out", benching.out, "Markdown file")->capture_default_str();
  benchStagesCommand->add_option("--frames", benching.frames, "timed frames per configuration")
      ->check(CLI::Range(1, 1000))->capture_default_str();
  benchStagesCommand->add_option("--scenes", benching.scenes, "comma-separated scenes")
      ->capture_default_str();
  benchStagesCommand->add_option("--width", benching.width)->check(CLI::Range(16, 4096));
  benchStagesCommand->add_option("--height", benching.height)->check(CLI::Range(16, 4096));
  benchStagesCommand->add_option("--map", benching.mapSize, "shadow-map size")
      ->check(CLI::Range(128, 2048));
  benchStagesCommand->add_option("--set", benching.sets, "stage.key=value for every configuration");

  BenchRaster4dOptions raster4dBench;
  CLI::App* benchRaster4dCommand = app.add_subcommand(
      "bench-raster4d", "raster4d (4D rasterization) timed against the Embree reference at the "
                        "same light samples, in the shapes of Wang et al.'s tables");
  benchRaster4dCommand->add_option("--out", raster4dBench.out, "Markdown file")->required();
  benchRaster4dCommand->add_option("--scenes", raster4dBench.scenes, "comma-separated scenes")
      ->capture_default_str();
  benchRaster4dCommand->add_option("--toggle-scenes", raster4dBench.toggleScenes,
                                   "scenes whose Table 2 variants are timed (default: all)");
  benchRaster4dCommand->add_option("--frames", raster4dBench.frames, "timed runs per configuration")
      ->check(CLI::Range(1, 100))->capture_default_str();
  benchRaster4dCommand->add_option("--width", raster4dBench.width)->check(CLI::Range(16, 4096));
  benchRaster4dCommand->add_option("--height", raster4dBench.height)->check(CLI::Range(16, 4096));

  BenchHierarchyOptions hierarchyBench;
  CLI::App* benchHierarchyCommand = app.add_subcommand(
      "bench-hierarchy", "N-buffer against min-max mipmap, back to back per map size: build "
                         "time, memory, fetches per searched ray, trace time");
  benchHierarchyCommand->add_option("--out", hierarchyBench.out, "Markdown file")->required();
  benchHierarchyCommand->add_option("--frames", hierarchyBench.frames, "timed frames per hierarchy")
      ->check(CLI::Range(1, 1000))->capture_default_str();
  benchHierarchyCommand->add_option("--scene", hierarchyBench.scene)->capture_default_str();
  benchHierarchyCommand->add_option("--maps", hierarchyBench.maps, "shadow-map sizes")
      ->check(CLI::Range(128, 2048))->delimiter(',');
  benchHierarchyCommand->add_option("--width", hierarchyBench.width)->check(CLI::Range(16, 4096));
  benchHierarchyCommand->add_option("--height", hierarchyBench.height)->check(CLI::Range(16, 4096));
  benchHierarchyCommand->add_option("--set", hierarchyBench.sets, "stage.key=value for both");

  BenchCompareOptions compareBench;
  CLI::App* benchCompareCommand = app.add_subcommand(
      "bench-compare", "configurations timed back to back, frames alternating: per-stage "
                       "medians, counters, error against the reference, ratios");
  benchCompareCommand->add_option("--out", compareBench.out, "Markdown file")->capture_default_str();
  benchCompareCommand->add_option("--title", compareBench.title, "the table's heading");
  benchCompareCommand->add_option("--scene", compareBench.scene)->capture_default_str();
  benchCompareCommand->add_option("--frames", compareBench.frames, "timed frames per side")
      ->check(CLI::Range(1, 1000))->capture_default_str();
  benchCompareCommand->add_option("--warmup", compareBench.warmup, "untimed frames first")
      ->check(CLI::Range(0, 100))->capture_default_str();
  benchCompareCommand->add_option("--width", compareBench.width)->check(CLI::Range(16, 4096));
  benchCompareCommand->add_option("--height", compareBench.height)->check(CLI::Range(16, 4096));
  benchCompareCommand->add_option("--set", compareBench.sets, "stage.key=value for every side");
  benchCompareCommand->add_option("--side", compareBench.sides,
                                  "label:stage.key=value;stage.key=value (repeatable)")->required();
  benchCompareCommand->add_option("--requested", compareBench.requested,
                                  "outputs to run for (default: every stage)")->delimiter(',');
  benchCompareCommand->add_option("--counters", compareBench.counters,
                                  "frame counters to report")->delimiter(',');
  benchCompareCommand->add_option("--error-of", compareBench.errorOf,
                                  "a method whose error against the reference to report");

  BenchTemporalOptions temporalBench;  // app/bench/bench_temporal.h: why its own command
  CLI::App* benchTemporalCommand = app.add_subcommand(
      "bench-temporal", "temporal stability per method over a range of frames: mean and worst "
                        "frame-to-frame change where the reference did not change, and its ratio "
                        "to the reference's own change (Markdown table + per-frame CSV)");
  benchTemporalCommand->add_option("--scene", temporalBench.scene)->capture_default_str();
  benchTemporalCommand->add_option("--out", temporalBench.out, "Markdown file (the CSV beside it)")->capture_default_str();
  benchTemporalCommand->add_option("--title", temporalBench.title, "the table's heading");
  benchTemporalCommand->add_option("--time-range", temporalBench.timeRange, "START:END seconds")->capture_default_str();
  benchTemporalCommand->add_option("--fps", temporalBench.fps, "frames per second of the range")->capture_default_str();
  benchTemporalCommand->add_option("--keys", temporalBench.keys, "fixed (key 0), per_frame (key = frame), or both")
      ->delimiter(',')->capture_default_str();
  benchTemporalCommand->add_option("--width", temporalBench.width)->check(CLI::Range(16, 4096))->capture_default_str();
  benchTemporalCommand->add_option("--height", temporalBench.height)->check(CLI::Range(16, 4096))->capture_default_str();
  benchTemporalCommand->add_option("--set", temporalBench.sets, "stage.key=value for every side and the reference");
  benchTemporalCommand->add_option("--side", temporalBench.sides, "[label=]method[:stage.key=value;...] "
                                   "(repeatable; default: every method that runs by default)");
  benchTemporalCommand->add_option("--reference-samples", temporalBench.referenceSamples, "m: m x m light "
                                   "samples per pixel in the reference")->check(CLI::Range(1, 64))->capture_default_str();

  BenchOptions report;
  CLI::App* benchCommand = app.add_subcommand(
      "bench", "speed against error: every configuration timed and compared with the exact "
               "reference (writes results.json, results.csv, results.md and charts as PNG, SVG, PDF)");
  benchCommand->add_option("--scene", report.scene, "built-in scene or scene file")->capture_default_str();
  benchCommand->add_option("--time", report.time, "seconds into the scene's animation (every "
                           "configuration measured on the scene posed at that time)")
      ->capture_default_str();
  benchCommand->add_option("--preset", report.preset, "default, minimal, thesis-table-4.1, atty-4.2, "
                           "animated (an animated scene's whole cycle, frame by frame)");
  benchCommand->add_option("--sweep", report.sweeps, "stage.key=v1,v2,... or scene.light_scale=, "
                                                     "scene.lateral=, scene.vertical=, eye.size=WxH,...");
  benchCommand->add_option("--set", report.sets, "stage.key=value for every configuration, repeatable");
  benchCommand->add_option("--out", report.out, "output directory")->required();
  benchCommand->add_option("--width", report.width, "eye width (default: the preset's)")->check(CLI::Range(16, 4096));
  benchCommand->add_option("--height", report.height, "eye height (default: the preset's)")->check(CLI::Range(16, 4096));
  benchCommand->add_option("--frames", report.frames, "timed frames per configuration")
      ->check(CLI::Range(1, 1000))->capture_default_str();
  benchCommand->add_option("--warmup", report.warmup, "untimed frames first")
      ->check(CLI::Range(0, 100))->capture_default_str();
  benchCommand->add_option("--rounds", report.rounds, "passes over the configurations that "
                           "share the timed frames")->check(CLI::Range(1, 100))->capture_default_str();
  benchCommand->add_option("--reference-samples", report.referenceSamples, "m: m x m light samples "
                           "per pixel in the reference")->check(CLI::Range(1, 64))->capture_default_str();
  benchCommand->add_option("--fps", report.fps, "preset animated: frames per second over one "
                           "cycle of the animation")->check(CLI::Range(0.01, 240.0))->capture_default_str();
  benchCommand->add_option("--loop-frames", report.loopFrames, "preset animated: only the first N "
                           "frames of the cycle (0: all)")->check(CLI::Range(0, 100000))->capture_default_str();
  benchCommand->add_option("--time-limit", report.timeLimit, "seconds of reference tracing allowed "
                           "(estimated before starting)")->check(positiveSeconds)->capture_default_str();

  CLI::App* graphCommand = app.add_subcommand(
      "graph", "print the stage graph (stages/registry.cpp) as Graphviz dot: "
               "penumbra graph | dot -Tsvg > graph.svg");
  bool graphMarkdown = false;
  graphCommand->add_flag("--markdown", graphMarkdown, "print the README's stage table as Markdown "
                         "instead (scripts/stage_docs.sh)");

  CalibrateOptions calibrating;
  CLI::App* calibrateCommand = app.add_subcommand(
      "calibrate", "measure (or show the cached) crossovers `auto` uses on this renderer");
  calibrateCommand->add_flag("--refresh", calibrating.refresh, "measure again, rewrite the cache");
  CLI::App* shadersCommand = app.add_subcommand(
      "shaders", "write the final GLSL source of every program variant the pipeline can build "
                 "(one file per shader stage, and programs.txt), for checking with any compiler");
  std::string shaderDumpDirectory;
  shadersCommand->add_option("--dump", shaderDumpDirectory, "directory to write to")->required();
  // --time-limit on every command but bench (whose --time-limit bounds its reference tracing,
  // estimated before it starts): the run is cancelled at the next check after that many
  // seconds (between stages, SSM passes, reference tiles) and the command exits 1 with
  // nothing half-written (core/run_control.h).
  std::string timeLimit;
  const char* timeLimitHelp = "seconds the command may run; then it stops at the next check "
                              "(between stages, SSM passes, reference tiles) and exits 1, "
                              "writing nothing";
  app.add_option("--time-limit", timeLimit, timeLimitHelp)->check(positiveSeconds);
  for (CLI::App* sub : app.get_subcommands({}))
    if (sub != benchCommand && sub != graphCommand)
      sub->add_option("--time-limit", timeLimit, timeLimitHelp)->check(positiveSeconds);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::CallForAllHelp& help) {
    return app.exit(help);
  } catch (const CLI::ParseError& error) {
    app.exit(error);
    return 2;
  }

  const std::string command = app.get_subcommands().empty() ? "" : app.get_subcommands()[0]->get_name();
  return runCommand(command, [&] {
    const RunTimeLimit limit(timeLimit.empty() ? 0.0 : std::strtod(timeLimit.c_str(), nullptr));
    if (*graphCommand) {
      const Pipeline pipeline;
      std::fputs((graphMarkdown ? stageTableMarkdown(pipeline) : pipeline.dot()).c_str(), stdout);
      return 0;
    }
    if (*shadersCommand) {
      const int programs = dumpShaderSources(shaderDumpDirectory);
      std::printf("%d programs written to %s (programs.txt lists them)\n", programs,
                  shaderDumpDirectory.c_str());
      return 0;
    }
    if (*calibrateCommand) return runCalibrateCommand(calibrating);
    if (*exportCommand) return runExport(exporting);
    if (*traceCommand) return runTraceCommand(tracing);
    if (*benchStagesCommand) return runBenchStages(benching);
    if (*benchRaster4dCommand) return runBenchRaster4d(raster4dBench);
    if (*benchHierarchyCommand) return runBenchHierarchy(hierarchyBench);
    if (*benchCompareCommand) return runBenchCompare(compareBench);
    if (*benchTemporalCommand) {
      for (int i = 0; i < argc; ++i) temporalBench.commandLine += (i ? " " : "") + std::string(i ? argv[i] : "penumbra");
      return runBenchTemporal(temporalBench);
    }
    if (*benchCommand) {
      for (int i = 0; i < argc; ++i) report.commandLine += (i ? " " : "") + std::string(i ? argv[i] : "penumbra");
      return runBench(report);
    }
    if (*hashCommand) return runHashCommand(hashing);
    if (*hashStatsCommand) return runHashStatsCommand(hashStats);
    if (*lessonCommand) {
      const CliProgress progress("lesson");  // a lesson exported: a bar on stderr (core/progress.h)
      lesson.interactiveLesson = lesson.exportDirectory.empty();
      lesson.lessonCommand = true;
      return runWindow(lesson);
    }
    return runWindow(window);
  });
}
