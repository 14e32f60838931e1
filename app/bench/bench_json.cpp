#include "bench/bench_json.h"

#include <nlohmann/json.hpp>

using nlohmann::json;

std::vector<BenchSetupInfo> setupInfos(const std::vector<BenchSetup>& setups) {
  std::vector<BenchSetupInfo> infos;
  for (const BenchSetup& s : setups)
    infos.push_back({s.label, s.axis, s.axisValue, s.width, s.height, s.fps, s.cycle, s.loopTimes, s.poseMs});
  return infos;
}

std::string benchJson(const BenchRunInfo& info, const std::vector<BenchSetupInfo>& setups,
                      const std::vector<BenchResult>& results) {
  json root = {{"scene", info.scene},          {"preset", info.preset},
               {"command", info.commandLine},  {"started", info.started},
               {"renderer", info.renderer},    {"cpu", info.cpu},
               {"load_before", info.loadBefore}, {"load_after", info.loadAfter},
               {"frames", info.frames},        {"warmup", info.warmup},
               {"rounds", info.rounds},        {"reference_samples", info.referenceSamples},
               {"seconds", info.seconds}};
  json& jsonSetups = root["setups"] = json::array();
  for (const BenchSetupInfo& s : setups)
    jsonSetups.push_back({{"label", s.label}, {"axis", s.axis}, {"axis_value", s.axisValue},
                          {"width", s.width}, {"height", s.height}, {"fps", s.fps},
                          {"cycle", s.cycle}, {"loop_times", s.loopTimes}, {"pose_ms", s.poseMs}});
  json& jsonResults = root["results"] = json::array();
  for (const BenchResult& r : results)
    jsonResults.push_back(
        {{"setup", r.setup}, {"config", r.label}, {"method", r.method}, {"family", r.family},
         {"sets", r.sets}, {"stages", r.stages}, {"parameters", r.params}, {"shadow_map", r.map},
         {"frames", r.frames}, {"ms_median", r.msMedian}, {"ms_min", r.msMin}, {"ms_max", r.msMax},
         {"stage_ms_median", r.stageMs}, {"counters", r.counters},
         {"error", {{"rmse", r.error.rmse}, {"max", r.error.max},
                    {"mean_abs_in_shadow", r.error.meanAbsInShadow}, {"p99", r.error.p99},
                    {"mean_signed", r.error.meanSigned}, {"pixels", r.error.pixels},
                    {"pixels_in_shadow", r.error.pixelsInShadow}}},
         {"reference_seconds", r.referenceSeconds}, {"reference_cache", r.referenceCache},
         {"pareto", r.pareto}, {"bvh_ms_median", r.bvhMsMedian}, {"bvh_ms_max", r.bvhMsMax},
         {"loop_times", r.loopTimes}, {"loop_ms", r.loopMs}, {"loop_bvh_ms", r.loopBvhMs}});
  return root.dump(1) + "\n";
}

std::string parseBenchJson(const std::string& text, BenchRunInfo& info,
                           std::vector<BenchSetupInfo>& setups, std::vector<BenchResult>& results) {
  setups.clear();
  results.clear();
  try {
    const json root = json::parse(text);
    info.scene = root.at("scene").get<std::string>();
    info.preset = root.at("preset").get<std::string>();
    info.commandLine = root.at("command").get<std::string>();
    info.started = root.at("started").get<std::string>();
    info.renderer = root.at("renderer").get<std::string>();
    info.cpu = root.at("cpu").get<std::string>();
    info.loadBefore = root.at("load_before").get<std::string>();
    info.loadAfter = root.at("load_after").get<std::string>();
    info.frames = root.at("frames").get<int>();
    info.warmup = root.at("warmup").get<int>();
    info.rounds = root.at("rounds").get<int>();
    info.referenceSamples = root.at("reference_samples").get<int>();
    info.seconds = root.at("seconds").get<double>();
    // Fields added later (the loop's, the BVH's) default when absent: older files still load.
    const std::vector<double> none;
    for (const json& s : root.at("setups"))
      setups.push_back({s.at("label").get<std::string>(), s.at("axis").get<std::string>(),
                        s.at("axis_value").get<double>(), s.at("width").get<int>(),
                        s.at("height").get<int>(), s.value("fps", 0.0), s.value("cycle", 0.0),
                        s.value("loop_times", none), s.value("pose_ms", none)});
    for (const json& j : root.at("results")) {
      BenchResult r;
      r.setup = j.at("setup").get<size_t>();
      if (r.setup >= setups.size()) return "result '" + j.value("config", "") + "': no setup " + std::to_string(r.setup);
      r.label = j.at("config").get<std::string>();
      r.method = j.at("method").get<std::string>();
      r.family = j.at("family").get<std::string>();
      r.sets = j.at("sets").get<std::vector<std::string>>();
      r.stages = j.at("stages").get<std::vector<std::string>>();
      r.params = j.at("parameters").get<std::map<std::string, std::string>>();
      r.map = j.at("shadow_map").get<int>();
      r.frames = j.at("frames").get<int>();
      r.msMedian = j.at("ms_median").get<double>();
      r.msMin = j.at("ms_min").get<double>();
      r.msMax = j.at("ms_max").get<double>();
      r.stageMs = j.at("stage_ms_median").get<std::map<std::string, double>>();
      r.counters = j.at("counters").get<std::map<std::string, double>>();
      const json& e = j.at("error");
      r.error.rmse = e.at("rmse").get<double>();
      r.error.max = e.at("max").get<double>();
      r.error.meanAbsInShadow = e.at("mean_abs_in_shadow").get<double>();
      r.error.p99 = e.at("p99").get<double>();
      r.error.meanSigned = e.at("mean_signed").get<double>();
      r.error.pixels = e.at("pixels").get<size_t>();
      r.error.pixelsInShadow = e.at("pixels_in_shadow").get<size_t>();
      r.referenceSeconds = j.at("reference_seconds").get<double>();
      r.referenceCache = j.at("reference_cache").get<int>();
      r.pareto = j.at("pareto").get<bool>();
      r.bvhMsMedian = j.value("bvh_ms_median", 0.0);
      r.bvhMsMax = j.value("bvh_ms_max", 0.0);
      r.loopTimes = j.value("loop_times", none);
      r.loopMs = j.value("loop_ms", none);
      r.loopBvhMs = j.value("loop_bvh_ms", none);
      results.push_back(std::move(r));
    }
  } catch (const json::exception& error) {
    return std::string("not a bench results.json: ") + error.what();
  }
  return "";
}
