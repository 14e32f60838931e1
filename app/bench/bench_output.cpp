#include "bench/bench_output.h"

#include "io/output_path.h"

#include <algorithm>
#include <functional>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

#include "io/image_export.h"
#include "bench/bench_measure.h"
#include "bench/pareto.h"
#include "bench/plot.h"

namespace {

std::string fixed(double value, int decimals) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

std::string fileSafe(const std::string& text) {
  std::string safe;
  for (char c : text) safe += std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' ? c : '_';
  return safe;
}

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

const char* cacheName(int cache) { return cache == 0 ? "computed" : cache == 1 ? "memory" : "disk"; }

std::string joined(const std::vector<std::string>& parts, const std::string& separator) {
  std::string text;
  for (const std::string& part : parts) text += (text.empty() ? "" : separator) + part;
  return text;
}

// "gbuffer 3.1, light_layers 10.2, ...": each timed stage's median, in execution order.
std::string stageTimes(const BenchResult& r, const std::string& separator = ", ") {
  std::vector<std::string> parts;
  for (const std::string& stage : r.stages)
    if (r.stageMs.count(stage)) parts.push_back(stage + " " + fixed(r.stageMs.at(stage), 1));
  return joined(parts, separator);
}

// An animated setup's worst frame: its time in the loop (0 without a loop).
double worstFrameTime(const BenchResult& r) {
  if (r.loopMs.empty() || r.loopMs.size() != r.loopTimes.size()) return 0;
  return r.loopTimes[size_t(std::max_element(r.loopMs.begin(), r.loopMs.end()) - r.loopMs.begin())];
}

// loop.csv: one row per frame of an animated setup and configuration.
std::string loopCsv(const std::vector<BenchSetup>& setups, const std::vector<BenchResult>& results) {
  std::ostringstream out;
  out << "setup,config,method,frame,time,ms,bvh_ms,pose_upload_ms\n";
  for (const BenchResult& r : results) {
    const BenchSetup& s = setups[r.setup];
    for (size_t i = 0; i < r.loopMs.size() && i < r.loopTimes.size(); ++i) {
      out << csvField(s.label) << "," << csvField(r.label) << "," << r.method << "," << i << ","
          << fixed(r.loopTimes[i], 4) << "," << fixed(r.loopMs[i], 3) << ","
          << (r.loopBvhMs.size() > i ? fixed(r.loopBvhMs[i], 3) : std::string("")) << ","
          << (i < s.poseMs.size() ? fixed(s.poseMs[i], 3) : "") << "\n";
    }
  }
  return out.str();
}

std::string csv(const BenchRunInfo& info, const std::vector<BenchSetup>& setups,
                const std::vector<BenchResult>& results) {
  std::ostringstream out;
  const auto columns = benchCsvColumns();
  for (size_t i = 0; i < columns.size(); ++i) out << (i ? "," : "") << columns[i];
  out << "\n";
  for (const BenchResult& r : results) {
    const BenchSetup& s = setups[r.setup];
    const std::vector<std::string> fields = {
        s.label, info.scene, std::to_string(s.width), std::to_string(s.height), s.axis,
        s.axis.empty() ? "" : fixed(s.axisValue, 4), r.label, r.method, r.family,
        joined(r.sets, " "), joined(r.stages, "+"), std::to_string(r.map), std::to_string(r.frames),
        fixed(r.msMedian, 3), fixed(r.msMin, 3), fixed(r.msMax, 3), stageTimes(r, "; "),
        fixed(r.error.rmse, 6), fixed(r.error.max, 6),
        fixed(r.error.meanAbsInShadow, 6), fixed(r.error.p99, 6), fixed(r.error.meanSigned, 6),
        std::to_string(r.error.pixels), std::to_string(r.error.pixelsInShadow),
        std::to_string(info.referenceSamples * info.referenceSamples), fixed(r.referenceSeconds, 3),
        cacheName(r.referenceCache), r.pareto ? "1" : "0", fixed(r.bvhMsMedian, 3),
        fixed(r.bvhMsMax, 3), std::to_string(r.loopMs.size()), fixed(worstFrameTime(r), 4)};
    for (size_t i = 0; i < fields.size(); ++i) out << (i ? "," : "") << csvField(fields[i]);
    out << "\n";
  }
  return out.str();
}

int rays(const BenchResult& r) {
  const auto it = r.params.find("trace.rays");
  return it == r.params.end() ? 0 : std::atoi(it->second.c_str());
}

// The Monte Carlo tables below: a result by family, rays per side and map size.
const BenchResult* find(const std::vector<BenchResult>& results, size_t setup,
                        const std::string& family, int rays, int map) {
  for (const BenchResult& r : results)
    if (r.setup == setup && r.family == family && (rays == 0 || ::rays(r) == rays) && r.map == map)
      return &r;
  return nullptr;
}

// "hierarchical 2L 2x2 forward" -> the thesis's row names.
std::string thesisCell(const BenchResult* r) {
  if (!r) return "-";
  return fixed(r->msMedian, 0) + " ms (" + fixed(1000.0 / r->msMedian, 1) + " fps)";
}

// The thesis's frames per second (§4.2, Nvidia 8800 GTS), rows as in thesisTables: Tables
// 4.1 (dragon) and 4.2 (cube) at 1024x768 by map 256/512/1024; Tables 4.3 (dragon) and 4.4
// (cube) at map 512 by screen 800x600/1024x768/1280x1024.
constexpr double kThesisByMap[2][6][3] = {
    {{46, 40, 28}, {37, 34, 21}, {30, 26, 18}, {18, 16, 12}, {25, 18, 15}, {12, 11, 10}},
    {{70, 50, 35}, {60, 45, 31}, {66, 47, 34}, {50, 44, 30}, {36, 32, 23}, {25, 22, 17}}};
constexpr double kThesisByScreen[2][6][3] = {
    {{45, 40, 32}, {40, 34, 22}, {33, 26, 19}, {20, 16, 12}, {27, 18, 14}, {17, 11, 8}},
    {{74, 50, 41}, {61, 45, 34}, {70, 47, 41}, {49, 44, 35}, {41, 32, 23}, {31, 22, 15}}};

// Ours beside the thesis's as ratios (absolute frame rates of a 2009 GPU and llvmpipe do not
// compare): hierarchical over linear/binary and deferred over forward (time of the slower
// over time of the faster, = fps ratio), and the frame rate at the last column over the
// first (256 -> 1024 maps, 800x600 -> 1280x1024 screens).
void thesisRatios(std::ostringstream& md, const std::string& scene, const char* axis,
                  const double (&thesis)[6][3], const std::vector<std::string>& columns,
                  const std::function<const BenchResult*(int row, int column)>& at) {
  auto ratio = [&](int slowRow, int fastRow, int column) {
    const BenchResult *slow = at(slowRow, column), *fast = at(fastRow, column);
    return std::make_pair(slow && fast ? fixed(slow->msMedian / fast->msMedian, 2) + "x" : "-",
                          fixed(thesis[fastRow][column] / thesis[slowRow][column], 2) + "x");
  };
  md << "Ratios beside the thesis's (" << scene << "; by " << axis << "): ours / thesis\n\n| ratio | rays |";
  for (const std::string& column : columns) md << " " << column << " |";
  md << "\n|---|---|";
  for (size_t c = 0; c < columns.size(); ++c) md << "---|";
  md << "\n";
  for (int rays = 0; rays < 2; ++rays) {
    md << "| hierarchical / linear-binary, deferred | " << rays + 2 << "x" << rays + 2;
    for (int c = 0; c < 3; ++c) {
      const auto [ours, theirs] = ratio(4 + rays, rays, c);
      md << " | " << ours << " / " << theirs;
    }
    md << " |\n| deferred / forward, hierarchical | " << rays + 2 << "x" << rays + 2;
    for (int c = 0; c < 3; ++c) {
      const auto [ours, theirs] = ratio(2 + rays, rays, c);
      md << " | " << ours << " / " << theirs;
    }
    md << " |\n";
  }
  for (int row = 0; row < 6; ++row) {
    const BenchResult *first = at(row, 0), *last = at(row, 2);
    const char* names[3] = {"hierarchical, deferred", "hierarchical, forward", "linear-binary, deferred"};
    md << "| fps " << columns[2] << " / fps " << columns[0] << ", " << names[row / 2] << " | "
       << (row % 2 ? "3x3" : "2x2") << " | | | "
       << (first && last ? fixed(first->msMedian / last->msMedian, 2) : "-") << " / "
       << fixed(thesis[row][2] / thesis[row][0], 2) << " |\n";
  }
  md << "\n";
}

void thesisTables(std::ostringstream& md, const std::vector<BenchSetup>& setups,
                  const std::vector<BenchResult>& results, const std::string& scene) {
  struct Row { std::string family, search, deferred; int rays; };
  const std::vector<Row> rows = {{"hierarchical 2L", "hierarchical", "yes", 2},
                                 {"hierarchical 2L", "hierarchical", "yes", 3},
                                 {"hierarchical 2L forward", "hierarchical", "no", 2},
                                 {"hierarchical 2L forward", "hierarchical", "no", 3},
                                 {"linear/binary 3L", "linear/binary (3 layers)", "yes", 2},
                                 {"linear/binary 3L", "linear/binary (3 layers)", "yes", 3}};
  md << "## Thesis Table 4.1/4.2 shape: shadow-map resolution (eye " << setups[0].width << "x"
     << setups[0].height << ")\n\n| search type | rays | deferred | 256x256 | 512x512 | 1024x1024 |\n|---|---|---|---|---|---|\n";
  for (const Row& row : rows) {
    md << "| " << row.search << " | " << row.rays << "x" << row.rays << " | " << row.deferred;
    for (int map : {256, 512, 1024}) md << " | " << thesisCell(find(results, 0, row.family, row.rays, map));
    md << " |\n";
  }
  const int table = scene == "dragon" ? 0 : 1;  // the thesis's dragon, or its (elongated) cube
  md << "\n";
  thesisRatios(md, scene + " against the thesis's " + (table ? "cube, Table 4.2" : "dragon, Table 4.1"),
               "map", kThesisByMap[table], {"256", "512", "1024"}, [&](int row, int column) {
                 return find(results, 0, rows[row].family, rows[row].rays, 256 << column);
               });
  md << "\n## Thesis Table 4.3/4.4 shape: screen resolution (shadow map 512x512)\n\n| search type | rays | deferred |";
  std::vector<size_t> bySize(setups.size());
  for (size_t i = 0; i < setups.size(); ++i) bySize[i] = i;
  std::sort(bySize.begin(), bySize.end(), [&](size_t a, size_t b) {
    return setups[a].width * setups[a].height < setups[b].width * setups[b].height;
  });
  for (size_t s : bySize) md << " " << setups[s].width << "x" << setups[s].height << " |";
  md << "\n|---|---|---|";
  for (size_t i = 0; i < setups.size(); ++i) md << "---|";
  md << "\n";
  for (const Row& row : rows) {
    md << "| " << row.search << " | " << row.rays << "x" << row.rays << " | " << row.deferred;
    for (size_t s : bySize) md << " | " << thesisCell(find(results, s, row.family, row.rays, 512));
    md << " |\n";
  }
  md << "\n";
  if (bySize.size() == 3)
    thesisRatios(md, scene + " against the thesis's " + (table ? "cube, Table 4.4" : "dragon, Table 4.3"),
                 "screen", kThesisByScreen[table], {"small", "main", "large"}, [&](int row, int column) {
                   return find(results, bySize[column], rows[row].family, rows[row].rays, 512);
                 });
}

void attyTables(std::ostringstream& md, const std::vector<BenchSetup>& setups,
                const std::vector<BenchResult>& results) {
  std::vector<std::string> families;
  for (const BenchResult& r : results)
    if (std::find(families.begin(), families.end(), r.family) == families.end()) families.push_back(r.family);
  auto header = [&](const std::string& first) {
    md << "| " << first << " |";
    for (const std::string& f : families) md << " " << f << " |";
    md << "\n|---|";
    for (size_t i = 0; i < families.size(); ++i) md << "---|";
    md << "\n";
  };
  md << "## Atty et al. 2006 §4.2 shape: mean |error| over pixels in shadow\n\n"
     << "Receiver-only objects' pixels alone (error.pixels=receivers, §4.2.1: SSM computes "
        "no self-shadowing).\n\n"
     << "### Shadow-map size (§4.2.3)\n\n";
  header("map");
  std::set<int> maps;
  for (const BenchResult& r : results) if (setups[r.setup].axis == "map") maps.insert(r.map);
  for (int map : maps) {
    md << "| " << map;
    for (const std::string& f : families) {
      const BenchResult* r = nullptr;
      for (const BenchResult& each : results)
        if (setups[each.setup].axis == "map" && each.family == f && each.map == map) r = &each;
      md << " | " << (r ? fixed(r->error.meanAbsInShadow, 4) : "-");
    }
    md << " |\n";
  }
  for (const auto& [axis, title] : std::vector<std::pair<std::string, std::string>>{
           {"light_scale", "Light size, x the scene's light (§4.2.4; map 128)"},
           {"lateral", "Occluder moved laterally, in light widths from the light's axis (§4.2.5; map 128)"},
           {"vertical", "Occluder height: 0 touches the receiver, 1 the light (§4.2.6; map 128)"}}) {
    md << "\n### " << title << "\n\n";
    header(axis);
    for (size_t s = 0; s < setups.size(); ++s) {
      if (setups[s].axis != axis) continue;
      md << "| " << fixed(setups[s].axisValue, 2);
      for (const std::string& f : families) {
        const BenchResult* r = nullptr;
        for (const BenchResult& each : results) if (each.setup == s && each.family == f) r = &each;
        md << " | " << (r ? fixed(r->error.meanAbsInShadow, 4) : "-");
      }
      md << " |\n";
    }
  }
  md << "\n";
}

// The reference as a method: its BVH builds, apart from its trace (bench_reference.h).
void referenceNote(std::ostringstream& md, const std::vector<BenchResult>& results, size_t setup) {
  std::vector<std::string> parts;
  bool rebuilt = false;
  for (const BenchResult& r : results) {
    if (r.setup != setup || r.method != "reference") continue;
    rebuilt = rebuilt || r.stageMs.count("bvh_build");
    parts.push_back(r.label + ": BVH " + fixed(r.bvhMsMedian, 1) + " ms, trace " +
                    fixed(r.stageMs.count("embree_trace") ? r.stageMs.at("embree_trace") : 0, 1) + " ms");
  }
  if (parts.empty()) return;
  md << "The reference as a method (Embree on the CPU, m x m light samples at the cell centres, "
        "as raster4d samples the light; measured against the truth above): "
     << (rebuilt ? "its BVH is rebuilt every frame (the scene moves) and counted in its time"
                 : "its BVH is built once (the scene does not move) and not counted in its time")
     << "; medians: " << joined(parts, "; ") << ".\n\n";
}

// An animated setup (bench_animated.h): per configuration, the median and worst frame over
// the loop; Wang et al.'s comparison, raster4d against the reference at the same samples
// with its BVH rebuilt; every frame's milliseconds.
void loopTables(std::ostringstream& md, const BenchSetup& setup, size_t s,
                const std::vector<BenchResult>& results) {
  std::vector<const BenchResult*> rows;
  for (const BenchResult& r : results) if (r.setup == s) rows.push_back(&r);
  if (rows.empty()) return;
  md << "### Loop: " << setup.loopTimes.size() << " frames at " << fixed(setup.fps, 2)
     << " fps over the " << fixed(setup.cycle, 2) << " s cycle (t = "
     << fixed(setup.loopTimes.front(), 3) << " .. " << fixed(setup.loopTimes.back(), 3) << " s)\n\n"
     << "Each frame is the scene posed anew and uploaded as a new GPU scene and frame, so every "
        "stage recomputes from the posed geometry (light layers, hierarchies, shadow maps) and "
        "the reference rebuilds its BVH; per configuration one untimed run at the pose, then "
        "one timed frame. Posing + upload (charged to no method): median "
     << fixed(median(setup.poseMs), 1) << " ms, worst "
     << fixed(setup.poseMs.empty() ? 0 : *std::max_element(setup.poseMs.begin(), setup.poseMs.end()), 1)
     << " ms. Error: at the first frame's pose.\n\n"
     << "| configuration | method | median ms/frame | worst frame ms | worst at t (s) | BVH build median / worst ms | trace median ms | mean abs e in shadow |\n"
     << "|---|---|---|---|---|---|---|---|\n";
  for (const BenchResult* r : rows) {
    const bool reference = r->method == "reference";
    md << "| " << r->label << " | " << r->method << " | " << fixed(r->msMedian, 1) << " | "
       << fixed(r->msMax, 1) << " | " << fixed(worstFrameTime(*r), 3) << " | "
       << (reference ? fixed(r->bvhMsMedian, 1) + " / " + fixed(r->bvhMsMax, 1) : "-") << " | "
       << (reference && r->stageMs.count("embree_trace") ? fixed(r->stageMs.at("embree_trace"), 1) : "-")
       << " | " << fixed(r->error.meanAbsInShadow, 4) << " |\n";
  }
  // Wang et al. §5 (Fig. 1, Table 1): 4D rasterization against a ray tracer at the same
  // uniform light samples, which rebuilds its BVH every frame of the dynamic Toys (25x).
  std::ostringstream wang;
  for (const BenchResult* raster : rows) {
    if (raster->method != "raster4d") continue;
    const auto samples = raster->params.find("raster4d.samples");
    if (samples == raster->params.end()) continue;
    for (const BenchResult* ref : rows) {
      const auto m = ref->params.find("reference.samples");
      if (ref->method != "reference" || m == ref->params.end() || m->second != samples->second) continue;
      wang << "| " << samples->second << "x" << samples->second << " | " << fixed(raster->msMedian, 1)
           << " | " << fixed(ref->msMedian, 1) << " | " << fixed(ref->bvhMsMedian, 1) << " | "
           << fixed(ref->stageMs.count("embree_trace") ? ref->stageMs.at("embree_trace") : 0, 1)
           << " | **" << fixed(raster->msMedian / std::max(ref->msMedian, 1e-9), 3) << "** | "
           << fixed(ref->msMedian / std::max(raster->msMedian, 1e-9), 2) << "x |\n";
    }
  }
  if (!wang.str().empty())
    md << "\nWang et al.'s comparison, side by side in this run: raster4d (4D rasterization, on "
          "the GPU through OpenGL) against the reference ray tracer (Embree, CPU) at the same m x m "
          "uniform light samples, its BVH rebuilt every frame (theirs: Toys 15 fps against 0.60 fps "
          "with OptiX rebuilding its BVH, a 25x speed-up, Fig. 1). Medians over the loop:\n\n"
          "| samples | raster4d ms | reference ms (all) | its BVH build ms | its trace ms | raster4d / reference | speed-up of raster4d |\n"
          "|---|---|---|---|---|---|---|\n" << wang.str();
  md << "\nEvery frame (ms; loop.csv has them too):\n\n| frame | t (s) | pose + upload |";
  for (const BenchResult* r : rows) md << " " << r->label << " |";
  md << "\n|---|---|---|";
  for (size_t i = 0; i < rows.size(); ++i) md << "---|";
  md << "\n";
  for (size_t i = 0; i < setup.loopTimes.size(); ++i) {
    md << "| " << i << " | " << fixed(setup.loopTimes[i], 3) << " | "
       << (i < setup.poseMs.size() ? fixed(setup.poseMs[i], 1) : "-");
    for (const BenchResult* r : rows) md << " | " << (i < r->loopMs.size() ? fixed(r->loopMs[i], 1) : "-");
    md << " |\n";
  }
  md << "\n";
}

// An animated setup's milliseconds against the loop's time, a line per configuration.
PlotSpec frameTimesOf(const std::vector<BenchResult>& results, size_t setup, const std::string& title) {
  PlotSpec spec;
  spec.title = title;
  spec.xLabel = "time in the animation (s)";
  spec.yLabel = "milliseconds per frame (log)";
  spec.logX = false;
  spec.logY = true;
  spec.connectSeries = true;
  for (const BenchResult& r : results) {
    if (r.setup != setup || r.loopMs.empty()) continue;
    spec.seriesNames.push_back(r.label);
    for (size_t i = 0; i < r.loopMs.size() && i < r.loopTimes.size(); ++i)
      spec.points.push_back({r.loopTimes[i], r.loopMs[i], int(spec.seriesNames.size() - 1), r.label, false});
  }
  return spec;
}

// Plot series: the families in order of appearance.
PlotSpec scatterOf(const std::vector<BenchResult>& results, size_t setup, const std::string& title) {
  PlotSpec spec;
  spec.title = title;
  spec.xLabel = "milliseconds per frame (median over the method's stages, log scale)";
  spec.yLabel = "mean |visibility error| in shadow (Atty 2006), log";
  spec.frontierCaption = "Pareto frontier (ms, error):";
  spec.logY = true;  // the hard shadow's error is ~10x the Monte Carlo errors
  for (const BenchResult& r : results) {
    if (r.setup != setup) continue;
    const std::string legend = seriesLegend(r.method, r.family);  // plot.h
    auto it = std::find(spec.seriesNames.begin(), spec.seriesNames.end(), legend);
    if (it == spec.seriesNames.end()) { spec.seriesNames.push_back(legend); it = spec.seriesNames.end() - 1; }
    spec.points.push_back({r.msMedian, r.error.meanAbsInShadow, int(it - spec.seriesNames.begin()), r.label, r.pareto});
  }
  return spec;
}

}  // namespace

std::vector<std::string> benchCsvColumns() {
  return {"setup", "scene", "eye_width", "eye_height", "setup_axis", "setup_value", "config",
          "method", "family", "sets", "timed_stages", "shadow_map", "frames", "ms_median", "ms_min",
          "ms_max", "stage_ms_median", "rmse", "max_error", "mean_abs_error_in_shadow", "p99_abs_error", "mean_signed_error",
          "pixels", "pixels_in_shadow", "reference_samples", "reference_seconds",
          "reference_cache", "pareto", "bvh_ms_median", "bvh_ms_max", "loop_frames",
          "worst_frame_time"};
}

void markParetoFrontiers(std::vector<BenchResult>& results) {
  std::set<size_t> setups;
  for (const BenchResult& r : results) setups.insert(r.setup);
  for (size_t s : setups) {
    std::vector<size_t> members;
    std::vector<double> x, y;
    for (size_t i = 0; i < results.size(); ++i)
      if (results[i].setup == s) {
        members.push_back(i);
        x.push_back(results[i].msMedian);
        y.push_back(results[i].error.meanAbsInShadow);
      }
    const std::vector<bool> frontier = paretoFrontier(x, y);
    for (size_t k = 0; k < members.size(); ++k) results[members[k]].pareto = frontier[k];
  }
}

std::vector<std::filesystem::path> writeBenchOutputs(const std::filesystem::path& target,
                                                     const BenchRunInfo& info,
                                                     const std::vector<BenchSetup>& setups,
                                                     const std::vector<BenchResult>& results) {
  // Staged in a temporary directory, moved into place when every file is written.
  // The whole directory is one transaction (io/output_path.h): results.json, the manifest
  // that marks an earlier bench output, last; then one rename.
  DirectoryTransaction transaction(target, "results.json");
  const std::filesystem::path directory = transaction.path();
  std::vector<std::filesystem::path> written;
  writeTextFile(directory / "results.csv", csv(info, setups, results));
  written.push_back(directory / "results.csv");
  if (std::any_of(setups.begin(), setups.end(), [](const BenchSetup& s) { return s.animated(); })) {
    writeTextFile(directory / "loop.csv", loopCsv(setups, results));
    written.push_back(directory / "loop.csv");
  }

  // 1. How it was measured, and the stages each method's time covers (from the graph).
  std::ostringstream md;
  md << "# Speed against error: `" << info.scene << "`, preset `" << info.preset << "`\n\n"
     << "Produced by `" << info.commandLine << "` on " << info.started << " in "
     << fixed(info.seconds, 0) << " s.\n\n"
     << "- Machine: " << info.renderer << "; " << info.cpu << ".\n"
     << "- Load average (1, 5, 15 min) before: " << info.loadBefore << "; after: " << info.loadAfter
     << ". The cores are shared with other work: timings under load are noisy.\n"
     << "- Time: median of " << info.frames << " frames per configuration, taken in "
     << info.rounds << " rounds over all configurations of a setup (so load changes on the "
        "shared cores hit all of them alike), after " << info.warmup << " warm-up frames (1 after "
        "each switch); each frame runs only the stages the method's visibility depends on in "
        "the stage graph, timed with glFinish + steady clock per stage and summed. Not counted: "
        "composite, hash, reference, error.\n";
  if (std::any_of(setups.begin(), setups.end(), [](const BenchSetup& s) { return s.animated(); }))
    md << "- Animated setups (preset animated): the timed frames are instead one per frame of "
          "the animation's cycle, each at its own pose with everything rebuilt (one untimed run "
          "at the pose first); median and worst frame in each setup's loop table.\n";
  if (std::any_of(results.begin(), results.end(), [](const BenchResult& r) { return r.method == "reference"; }))
    md << "- The reference as a method (`reference m x m`): Embree on the CPU at m x m light "
          "samples at the cell centres, its time the G-buffer and light stages, the G-buffer's "
          "read-back, the trace on every core, and the BVH build where the scene moves; median "
          "of the same timed frames.\n";
  std::vector<std::string> charged;
  for (const BenchResult& r : results) {
    const std::string line = "`" + r.method + "`: " + joined(r.stages, " + ");
    if (std::find(charged.begin(), charged.end(), line) == charged.end()) charged.push_back(line);
  }
  md << "- Stages timed per method (its visibility's dependencies under the configuration's "
        "parameters): " << joined(charged, "; ") << ".\n"
     << "- Error: against the exact reference (" << info.referenceSamples << "x"
     << info.referenceSamples << " stratified light samples per pixel, real triangles, Embree "
        "on the CPU), over receiver pixels inside the light's map, on one frame (frame key 0). "
        "mean |e| in shadow = mean |error| over pixels whose reference < 1 (Atty et al. 2006 "
        "§4.2.1); RMSE and max by OpenImageIO `compare`; p99 = 99th percentile of |error|.\n"
     << "- Pareto: no other configuration of the same setup is both faster and more accurate "
        "(ms, mean |e| in shadow). Every number is also in results.json and results.csv.\n\n";

  // 2. One table per setup.
  for (size_t s = 0; s < setups.size(); ++s) {
    double referenceSeconds = 0;
    int cache = 2;
    for (const BenchResult& r : results)
      if (r.setup == s) { referenceSeconds = std::max(referenceSeconds, r.referenceSeconds); cache = std::min(cache, r.referenceCache); }
    md << "## " << setups[s].label << "\n\nReference: "
       << (cache == 0 ? "computed in " + fixed(referenceSeconds, 2) + " s"
                      : "from the disk cache (it took " + fixed(referenceSeconds, 2) + " s to trace)")
       << ".\n\n| configuration | method | ms/frame | min-max | stage medians (ms) | RMSE | max | mean abs e in shadow | p99 | Pareto |\n"
       << "|---|---|---|---|---|---|---|---|---|---|\n";
    std::vector<std::string> frontier;
    for (const BenchResult& r : results) {
      if (r.setup != s) continue;
      md << "| " << r.label << " | " << r.method << " | " << fixed(r.msMedian, 1) << " | "
         << fixed(r.msMin, 0) << "-" << fixed(r.msMax, 0) << " | " << stageTimes(r) << " | "
         << fixed(r.error.rmse, 4) << " | " << fixed(r.error.max, 3) << " | "
         << fixed(r.error.meanAbsInShadow, 4) << " | " << fixed(r.error.p99, 3) << " | "
         << (r.pareto ? "**yes**" : "") << " |\n";
      if (r.pareto) frontier.push_back(r.label);
    }
    md << "\nPareto frontier: " << joined(frontier, ", ") << ".\n\n";
    referenceNote(md, results, s);
    if (setups[s].animated()) loopTables(md, setups[s], s, results);
    // Speed ratio linear/binary : hierarchical at equal rays (thesis: 3.1x, dragon, 3x3).
    std::ostringstream ratios;
    for (const BenchResult& h : results) {
      if (h.setup != s || h.family != "hierarchical 2L") continue;
      for (const char* lb : {"linear/binary 2L", "linear/binary 3L"})
        if (const BenchResult* other = find(results, s, lb, rays(h), h.map)) {
          const double otherTrace = other->stageMs.count("trace") ? other->stageMs.at("trace") : 0;
          const double hTrace = h.stageMs.count("trace") ? h.stageMs.at("trace") : 0;
          ratios << "| " << rays(h) << "x" << rays(h) << " | " << h.map << " | " << lb << " | "
                 << fixed(other->msMedian, 1) << " | " << fixed(h.msMedian, 1) << " | **"
                 << fixed(other->msMedian / h.msMedian, 2) << "x** | " << fixed(otherTrace, 1)
                 << " | " << fixed(hTrace, 1) << " | **"
                 << fixed(otherTrace / std::max(hTrace, 1e-9), 2) << "x** |\n";
        }
    }
    if (!ratios.str().empty())
      md << "Speed ratio hierarchical : linear/binary at equal rays (time of linear/binary "
            "divided by time of hierarchical 2 layers; the thesis reports 3.1x on its dragon "
            "at 3x3, Table 4.1), for the method's stages and for the trace stage alone:\n\n"
            "| rays | map | versus | linear/binary ms | hierarchical ms | ratio | "
            "linear/binary trace ms | hierarchical trace ms | trace ratio |\n"
            "|---|---|---|---|---|---|---|---|---|\n" << ratios.str() << "\n";
  }
  if (info.preset == "thesis-table-4.1") thesisTables(md, setups, results, info.scene);
  if (info.preset == "atty-4.2") attyTables(md, setups, results);

  // 3. Charts: a speed-vs-error scatter for each setup with several configurations; for
  //    sweeps of a setup axis, error against the axis value.
  std::vector<std::string> charts;
  for (size_t s = 0; s < setups.size(); ++s) {
    size_t count = 0;
    for (const BenchResult& r : results) count += r.setup == s;
    // Setups of a scene/light sweep get the error-against-value charts below instead.
    const bool sweptSetup = !setups[s].axis.empty() && setups[s].axis != "map";
    if (count < 3 || (sweptSetup && count < 6)) continue;
    const std::string stem = s == 0 ? "speed_vs_error" : "speed_vs_error_" + fileSafe(setups[s].label);
    const std::string truth = std::to_string(info.referenceSamples) + "x" + std::to_string(info.referenceSamples);
    for (const auto& path : writePlot(directory / stem, scatterOf(results, s, "Speed against error: " + setups[s].label +
                                                                     " (truth: Embree " + truth + " stratified)")))
      written.push_back(path);
    charts.push_back(stem);
    if (!setups[s].animated()) continue;
    const std::string loopStem = "frame_times" + (s == 0 ? std::string() : "_" + fileSafe(setups[s].label));
    for (const auto& path : writePlot(directory / loopStem, frameTimesOf(results, s, "Milliseconds per frame over the loop: " + setups[s].label)))
      written.push_back(path);
    charts.push_back(loopStem);
  }
  std::map<std::string, PlotSpec> axisPlots;
  for (const BenchResult& r : results) {
    const BenchSetup& setup = setups[r.setup];
    if (setup.axis.empty()) continue;
    const bool map = setup.axis == "map";  // Atty Fig. 17: error against the map's size
    if (map && r.method == "reference") continue;  // it has no map: on the scatter only
    PlotSpec& spec = axisPlots[setup.axis];
    spec.title = "Error against " + setup.axis + ": " + info.scene;
    spec.xLabel = setup.axis + (map ? " (texels per side)" : setup.axis == "light_scale" ? " (x scene light)" : setup.axis == "lateral" ? " (light widths)" : " (0 receiver .. 1 light)");
    spec.yLabel = "mean |visibility error| in shadow (Atty 2006)";
    spec.logX = false;
    spec.connectSeries = true;
    const std::string legend = seriesLegend(r.method, r.family);  // plot.h
    auto it = std::find(spec.seriesNames.begin(), spec.seriesNames.end(), legend);
    if (it == spec.seriesNames.end()) { spec.seriesNames.push_back(legend); it = spec.seriesNames.end() - 1; }
    spec.points.push_back({map ? double(r.map) : setup.axisValue, r.error.meanAbsInShadow,
                           int(it - spec.seriesNames.begin()), r.label, false});
  }
  for (const auto& [axis, spec] : axisPlots) {
    const std::string stem = "error_vs_" + fileSafe(axis);
    for (const auto& path : writePlot(directory / stem, spec)) written.push_back(path);
    charts.push_back(stem);
  }
  if (!charts.empty()) {
    md << "Charts (drawn with cairo; each also as .svg and .pdf): ";
    for (const std::string& stem : charts) md << "![" << stem << "](" << stem << ".png) ";
    md << "\n";
  }
  writeTextFile(directory / "results.md", md.str());
  written.push_back(directory / "results.md");
  writeTextFile(directory / "results.json", benchJson(info, setupInfos(setups), results));
  written.push_back(directory / "results.json");
  transaction.commit();
  for (auto& path : written) path = transaction.target() / path.filename();
  return written;
}
