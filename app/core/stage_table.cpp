#include "core/stage_table.h"

#include "core/pipeline.h"

namespace {

// A table cell: '|' would end the cell, so it is escaped.
std::string cell(const std::string& text) {
  std::string escaped;
  for (char c : text) {
    if (c == '|') escaped += '\\';
    escaped += c == '\n' ? ' ' : c;
  }
  return escaped;
}

std::string outputText(const Output& output) {
  std::string text = output.roles & kRoleShadowMethod ? "**" + output.name + "**" : output.name;
  std::string notes;
  auto note = [&](const char* what) { notes += (notes.empty() ? "" : ", ") + std::string(what); };
  if (output.roles & kRoleGroundTruth) note("ground truth");
  if (output.roles & kRoleHierarchy) note("hierarchy");
  if (output.isBuffer()) note("buffer");
  return notes.empty() ? text : text + " (" + notes + ")";
}

}  // namespace

std::string stageTableMarkdown(const Pipeline& pipeline) {
  std::string table = "| stage | source | what it does | outputs |\n|---|---|---|---|\n";
  for (const auto& stage : pipeline.stages()) {
    std::string outputs;
    for (const Output& output : stage->outputs()) {
      if (!outputs.empty()) outputs += ", ";
      outputs += outputText(output);
    }
    table += "| `" + stage->name() + "` | " + cell(stage->thesisSection()) + " | " +
             cell(stage->summary()) + " | " + cell(outputs) + " |\n";
  }
  return table;
}
