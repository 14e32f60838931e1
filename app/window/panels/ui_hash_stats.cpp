#include "window/panels/ui_hash_stats.h"

#include <imgui.h>

#include <cmath>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "gl/hash_kind.h"
#include "stats/dieharder_run.h"
#include "stats/hash_stats_gpu.h"
#include "window/ui_state.h"
#include "window/ui_widgets.h"

namespace {

using namespace hashstats;

ImVec4 verdictColour(double p) {
  switch (dieharderVerdict(p)) {
    case Verdict::Passed: return {0.55f, 0.9f, 0.55f, 1};
    case Verdict::Weak: return {1.0f, 0.75f, 0.3f, 1};
    case Verdict::Failed: return {1.0f, 0.35f, 0.35f, 1};
    case Verdict::NotApplicable: break;
  }
  return {0.6f, 0.6f, 0.6f, 1};
}

// 1. The stage's table, from its counters (p of key 0, KS over keys where K >= 2).
void drawTable(const UiState& state) {
  if (!state.session.frame) return;
  const auto& counters = state.session.frame->counters;
  // Wider than the panel (large UI scale): the table scrolls sideways instead of being cut.
  const float height = ImGui::GetFrameHeightWithSpacing() * float(std::size(kTestNames) + 2);
  if (!ImGui::BeginTable("hash_stats_table", 4, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollX,
                         {0, height}))
    return;
  ImGui::TableSetupColumn("test");
  ImGui::TableSetupColumn("p");
  ImGui::TableSetupColumn("dieharder");
  ImGui::TableSetupColumn("thesis [0.01, 0.99]");
  ImGui::TableHeadersRow();
  for (const char* name : kTestNames) {
    const auto found = counters.find(std::string("hash_stats.") + name + ".p");
    const double p = found == counters.end() ? NAN : found->second;
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(name);
    ImGui::TableNextColumn();
    if (std::isnan(p)) ImGui::TextDisabled("n/a");
    else ImGui::Text("%.4g", p);
    ImGui::TableNextColumn();
    ImGui::TextColored(verdictColour(p), "%s", verdictName(dieharderVerdict(p)));
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(std::isnan(p) ? "n/a" : thesisPass(p) ? "pass" : "fail");
  }
  ImGui::EndTable();
}

// 2. Every hash on the stage's pattern, 2^16 samples each, with measured throughput.
using Comparison = HashStatsPanelState::Comparison;

void drawComparison(UiState& state, std::unique_ptr<Comparison>& comparison) {
  const bool compare = ImGui::Button("compare all hashes");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Every hash on this pattern, 2^16 samples each, with its GPU throughput.");
  if (compare) {
    GpuHashStats gpu;
    comparison = std::make_unique<Comparison>();
    const int pattern = state.session.pipeline.param("hash_stats.pattern").asInt();
    for (size_t kind = 0; kind < kHashKindNames.size(); ++kind) {
      comparison->hashes.push_back(kHashKindNames[kind]);
      comparison->results.push_back(analyze(gpu.run(int(kind), pattern, 1 << 16, 0)));
      comparison->hashesPerSecond.push_back(gpu.hashesPerSecond(int(kind), 1 << 20));
    }
    state.status = "hash_stats: compared every hash (GPU throughput measured just now)";
  }
  if (!comparison) return;
  const float height = ImGui::GetFrameHeightWithSpacing() * float(comparison->hashes.size() + 2);
  if (!ImGui::BeginTable("hash_compare", int(kTestNames.size()) + 2,
                         ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollX,
                         {0, height}))
    return;
  ImGui::TableSetupColumn("hash");
  for (const char* name : kTestNames) ImGui::TableSetupColumn(name);
  ImGui::TableSetupColumn("M hashes/s");
  ImGui::TableHeadersRow();
  for (size_t h = 0; h < comparison->hashes.size(); ++h) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(comparison->hashes[h].c_str());
    for (const TestResult& test : comparison->results[h].tests) {
      ImGui::TableNextColumn();
      ImGui::TextColored(verdictColour(test.p), "%.2g", test.p);
    }
    ImGui::TableNextColumn();
    ImGui::Text("%.1f", comparison->hashesPerSecond[h] / 1e6);
  }
  ImGui::EndTable();
}

// 3. dieharder in the background.
void drawDieharder(UiState& state, std::unique_ptr<DieharderRun>& run) {
  static const std::string dieharder = findDieharder();
  if (dieharder.empty()) {
    ImGui::TextDisabled("dieharder is not installed (Debian package dieharder)");
    return;
  }
  const std::string hash = state.session.pipeline.param("hash_stats.hash").asEnum();
  if ((!run || run->finished()) && ImGui::Button(("run dieharder on " + hash).c_str())) {
    const auto key = std::uint32_t(state.session.pipeline.param("hash_stats.key").asInt());
    run = std::make_unique<DieharderRun>("/proc/self/exe", hash, diehardTests(), key);
    run->start();
    state.status = "dieharder: penumbra hash --hash " + hash + " --key " + std::to_string(key) +
                   " | dieharder -g 200, DIEHARD tests";
  }
  if (!run) return;
  if (!run->finished()) {
    char text[64];
    std::snprintf(text, sizeof text, "%s: test %d / %d", run->hash().c_str(), run->testsDone(),
                  run->testsTotal());
    ImGui::ProgressBar(float(run->testsDone()) / float(run->testsTotal()),
                       {ImGui::GetContentRegionAvail().x - buttonsWidth({"Cancel"}), 0}, text);
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) run->cancel();
  }
  int passed = 0, weak = 0, failed = 0, thesis = 0;
  const auto lines = run->lines();
  for (const DieharderLine& line : lines) {
    passed += line.assessment == "PASSED";
    weak += line.assessment == "WEAK";
    failed += line.assessment == "FAILED";
    thesis += thesisPass(line.p);
  }
  ImGui::TextWrapped("%s%s: %d passed, %d weak, %d failed of %zu p-values; %d in [0.01, 0.99]",
              run->hash().c_str(), run->cancelled() ? " (cancelled)" : "", passed, weak, failed,
              lines.size(), thesis);
  if (const int claim = thesisDiehardPasses(run->hash()); claim >= 0)
    ImGui::TextWrapped("thesis §3.1: %d of 15 DIEHARD tests passed", claim);
  if (!run->error().empty()) ImGui::TextColored({1, 0.4f, 0.4f, 1}, "%s", run->error().c_str());
  ImGui::TextWrapped("Under a perfect generator each p-value falls outside [0.01, 0.99] with "
                     "probability 0.02: all 18 land inside only 70%% of the time. A count that "
                     "moves by one or two between keys says nothing; a test that fails on every "
                     "key does. (The same key streams the same numbers, so the same p-values.)");
}

}  // namespace

void drawHashStatsPanel(UiState& state) {
  HashStatsPanelState& memory = state.panelMemory.hashStats;
  drawTable(state);
  drawComparison(state, memory.comparison);
  drawDieharder(state, memory.run);
}
