#include "bench/bench_temporal.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <set>
#include <sstream>

#include "base/input_error.h"
#include "core/pipeline.h"
#include "io/headless_session.h"
#include "io/image_export.h"
#include "io/output_path.h"
#include "reference/error_metrics.h"
#include "scene/animation.h"
#include "scene/scene_builtin.h"
#include "stats/temporal.h"

namespace {

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

// One side under one key mode: its pipeline, the last frame's arrays and every pair's change.
struct Run {
  TemporalSide side;
  bool perFrameKey = false;
  std::unique_ptr<Pipeline> pipeline;
  std::vector<float> previous;
  std::vector<TemporalChange> changes;
  std::vector<double> errors;      // mean |error| in shadow per frame
  std::set<int> maps;              // the light's map size each frame ran with (auto decides per frame)
};

bool disabled(const Pipeline& pipeline, const std::string& stage) {
  for (const Param& param : pipeline.stage(stage).params())
    if (param.key == "enabled" && param.type == Param::Type::Bool) return !param.asBool();
  return false;
}

void applyAll(Pipeline& pipeline, const std::vector<std::string>& sets, const std::string& what) {
  for (const std::string& assignment : sets)
    if (std::string problem = pipeline.set(assignment); !problem.empty())
      throw InputError(what + ": --set " + problem);
}

}  // namespace

TemporalSide parseTemporalSide(const std::string& spec) {
  TemporalSide side;
  std::string rest = spec;
  const size_t equals = rest.find('='), colon = rest.find(':');
  if (equals != std::string::npos && (colon == std::string::npos || equals < colon)) {
    side.label = rest.substr(0, equals);
    rest = rest.substr(equals + 1);
  }
  const size_t split = rest.find(':');
  side.method = rest.substr(0, split);
  if (split != std::string::npos) {
    const std::string sets = rest.substr(split + 1);
    for (size_t start = 0; start < sets.size();) {
      const size_t end = std::min(sets.find(';', start), sets.size());
      if (end > start) side.sets.push_back(sets.substr(start, end - start));
      start = end + 1;
    }
  }
  if (side.method.empty())
    throw InputError("--side '" + printable(spec) + "': expected [label=]method[:stage.key=value;...]");
  if (side.label.empty()) {
    side.label = side.method;
    for (const std::string& set : side.sets) side.label += " " + set;
  }
  return side;
}

int temporalFrames(const std::string& range, double fps, double& start) {
  const size_t colon = range.find(':');
  char* end = nullptr;
  const std::string first = range.substr(0, colon), second = colon == std::string::npos ? "" : range.substr(colon + 1);
  start = std::strtod(first.c_str(), &end);
  const bool startOk = !first.empty() && !*end;
  const double stop = std::strtod(second.c_str(), &end);
  const bool stopOk = !second.empty() && !*end;
  if (colon == std::string::npos || !startOk || !stopOk || !std::isfinite(start) || !std::isfinite(stop) ||
      std::abs(start) > 1e6 || std::abs(stop) > 1e6 || stop < start)
    throw InputError("--time-range '" + printable(range) + "': expected START:END in seconds, "
                     "START <= END, both finite");
  if (!std::isfinite(fps) || fps <= 0 || fps > 1000) throw InputError("--fps must be in (0, 1000]");
  const double frames = std::floor((stop - start) * fps + 1e-9) + 1;
  if (frames < 2) throw InputError("--time-range '" + printable(range) + "' at --fps " + format("%g", fps) +
                                   " holds one frame: the measure needs two or more");
  if (frames > 10000) throw InputError("--time-range at --fps: more than 10000 frames");
  return int(frames);
}

int runBenchTemporal(const BenchTemporalOptions& options) {
  double start = 0;
  const int frames = temporalFrames(options.timeRange, options.fps, start);
  checkOutputFile(options.out, "--out");
  const std::filesystem::path csvPath = std::filesystem::path(options.out).replace_extension(".csv");
  checkOutputFile(csvPath, "--out (its .csv)");
  for (const std::string& key : options.keys)
    if (key != "fixed" && key != "per_frame")
      throw InputError("--keys: '" + printable(key) + "' is not fixed or per_frame");
  if (options.keys.empty()) throw InputError("--keys: give fixed, per_frame or both");
  // The session's pipeline is the reference's: the common sets, the reference on, traced in
  // the foreground; it also gives the counted pixels (classify.mask).
  std::vector<std::string> truthSets = options.sets;
  for (const std::string& set : {std::string("reference.enabled=true"), std::string("reference.background=false"),
                                 "reference.samples=" + std::to_string(options.referenceSamples)})
    truthSets.push_back(set);
  HeadlessSession session;
  if (const int status = session.open("bench-temporal", options.scene, truthSets, options.width,
                                      options.height, start);
      status != 0)
    return status;
  std::vector<std::string> warnings;
  const Scene rest = loadScene(options.scene, warnings);
  for (int i = 0; i < frames; ++i)
    if (std::string problem = posedSceneProblem(rest, start + i / options.fps); !problem.empty())
      throw InputError(printable(options.scene, 200) + ": " + problem);

  // The sides: as given, or every shadow method that runs by default (not the reference).
  std::vector<TemporalSide> sides;
  for (const std::string& spec : options.sides) sides.push_back(parseTemporalSide(spec));
  if (sides.empty())
    for (const std::string& method : session.pipeline.methods())
      if (method != "reference" && !disabled(session.pipeline, method)) sides.push_back({method, method, {}});
  const std::vector<std::string> methods = session.pipeline.methods();
  std::vector<Run> runs;
  for (const TemporalSide& side : sides)
    for (const std::string& key : options.keys) {
      if (std::find(methods.begin(), methods.end(), side.method) == methods.end()) {
        std::string valid;
        for (const std::string& m : methods) valid += (valid.empty() ? "" : ", ") + m;
        throw InputError("--side " + printable(side.label) + ": '" + printable(side.method) +
                         "' is not a shadow method; methods: " + valid);
      }
      Run run;
      run.side = side;
      run.perFrameKey = key == "per_frame";
      if (options.keys.size() > 1) run.side.label += run.perFrameKey ? ", key per frame" : ", key fixed";
      run.pipeline = std::make_unique<Pipeline>();
      applyAll(*run.pipeline, options.sets, "side " + side.label);
      applyAll(*run.pipeline, side.sets, "side " + side.label);
      if (disabled(*run.pipeline, side.method))
        throw InputError("--side " + printable(side.label) + ": " + side.method + " is disabled; add :" +
                         side.method + ".enabled=true");
      runs.push_back(std::move(run));
    }

  // Frame by frame: the pose, the reference and the mask once, then every side on it.
  const int w = options.width, h = options.height;
  std::vector<float> previousReference;
  std::vector<std::uint8_t> previousCounted;
  for (int i = 0; i < frames; ++i) {
    const double t = start + i / options.fps;
    const Scene posed = poseAt(rest, t);
    GpuScene gpuScene(posed);
    Frame truthFrame(posed, gpuScene, session.pipeline);
    truthFrame.eyeWidth = w, truthFrame.eyeHeight = h;
    session.pipeline.run(truthFrame, {"reference.visibility", "classify.mask"});
    const std::vector<float> reference = truthFrame.texture("reference.visibility").readFloats();
    const std::vector<std::uint8_t> counted = countedPixels(truthFrame.texture("classify.mask").readFloats());
    for (Run& run : runs) {
      Frame frame(posed, gpuScene, *run.pipeline);
      frame.eyeWidth = w, frame.eyeHeight = h;
      frame.frameKey = run.perFrameKey ? std::uint32_t(i) : 0u;
      const std::string output = run.pipeline->methodOutput(run.side.method);
      run.pipeline->run(frame, {output});
      std::vector<float> visibility = frame.texture(output).readFloats();
      run.maps.insert(int(frame.light.mapSize));  // 0: the method never ran the light stage
      run.errors.push_back(computeErrorMetrics(visibility, reference, counted, w, h).meanAbsInShadow);
      if (i > 0)
        run.changes.push_back(temporalChange(run.previous, visibility, previousReference, reference,
                                             bothCounted(previousCounted, counted, reference.size())));
      run.previous = std::move(visibility);
    }
    previousReference = reference;
    previousCounted = counted;
    std::fprintf(stderr, "\rpenumbra bench-temporal: frame %d of %d (t = %.3f s)", i + 1, frames, t);
  }
  std::fprintf(stderr, "\n");

  // The table, and every pair's numbers in the CSV.
  std::ostringstream table, csv;
  table << "## " << (options.title.empty() ? "Temporal stability" : options.title) << "\n\n"
        << "Scene " << options.scene << ", eye " << w << "x" << h << ", " << frames << " frames, t = "
        << format("%g", start) << " to " << format("%g", start + (frames - 1) / options.fps) << " s at "
        << format("%g", options.fps) << " fps; reference " << options.referenceSamples << "x"
        << options.referenceSamples << " light samples (Embree). Change: mean |visibility(frame) - "
        << "visibility(frame before)| over the pixels counted in both frames whose reference did "
        << "not change (decision 120); worst pixel change: the largest one pixel's change in any pair; ratio: mean change / mean reference change (\"-\": the "
        << "reference never changed).";
  if (!options.sets.empty()) {
    table << " Common sets:";
    for (const std::string& set : options.sets) table << " `" << set << "`";
    table << ".";
  }
  if (!options.commandLine.empty()) table << " Produced by `" << options.commandLine << "`.";
  table << "\n\n| side | key | map | pairs | mean change | worst change | worst pixel change | mean reference "
           "change | ratio | mean abs error in shadow |\n|---|---|---|---|---|---|---|---|---|---|\n";
  csv << "side,key,frame,time,change,max_change,reference_change,method_change,stable,counted,ratio,"
         "error_in_shadow\n";
  for (const Run& run : runs) {
    const TemporalSummary summary = summarizeTemporal(run.changes);
    std::string maps;
    for (int map : run.maps) maps += (maps.empty() ? "" : ", ") + std::to_string(map);
    double error = 0;
    for (double e : run.errors) error += e;
    error /= double(std::max<size_t>(1, run.errors.size()));
    table << "| " << run.side.label << " | " << (run.perFrameKey ? "per frame" : "fixed") << " | " << maps
          << " | " << summary.pairs << " | " << format("%.6f", summary.meanChange) << " | "
          << format("%.6f", summary.worstChange) << " | " << format("%.4f", summary.worstPixel) << " | "
          << format("%.6f", summary.meanReferenceChange)
          << " | " << (summary.hasRatio() ? format("%.3f", summary.ratio()) : "-") << " | "
          << format("%.5f", error) << " |\n";
    for (size_t p = 0; p < run.changes.size(); ++p) {
      const TemporalChange& c = run.changes[p];
      std::string label = run.side.label;
      std::replace(label.begin(), label.end(), ',', ';');
      csv << label << "," << (run.perFrameKey ? "per_frame" : "fixed") << "," << p + 1 << ","
          << format("%.6f", start + double(p + 1) / options.fps) << "," << format("%.8f", c.change) << ","
          << format("%.8f", c.maxChange) << "," << format("%.8f", c.referenceChange) << ","
          << format("%.8f", c.methodChange) << "," << c.stable << "," << c.counted << ","
          << (c.hasRatio() ? format("%.6f", c.ratio()) : "") << "," << format("%.6f", run.errors[p + 1])
          << "\n";
    }
  }
  const std::filesystem::path out(options.out);
  if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path());
  writeTextFile(csvPath, csv.str());
  writeTextFile(out, table.str());
  std::printf("%s\nwritten to %s (per frame: %s)\n", table.str().c_str(), options.out.c_str(),
              csvPath.string().c_str());
  return 0;
}
