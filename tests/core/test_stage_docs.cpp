// The README's stage table and docs/stage_graph.{dot,svg} are generated from the stage
// declarations (scripts/stage_docs.sh BUILD); these tests fail when the committed copies are
// stale, naming the script that refreshes them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "core/pipeline.h"
#include "core/stage_table.h"

namespace {

const std::string kRefresh = "run make stage-docs (or scripts/stage_docs.sh BUILD) and commit";

std::string readSourceFile(const std::string& relative) {
  std::ifstream file(std::string(PENUMBRA_SOURCE_DIR) + "/" + relative, std::ios::binary);
  EXPECT_TRUE(file) << "cannot read " << relative;
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

// The first line where two texts differ, both sides shown (an EXPECT_EQ of two whole tables
// is hard to read).
std::string firstDifference(const std::string& committed, const std::string& generated,
                            const std::string& nameA = "committed",
                            const std::string& nameB = "generated") {
  std::istringstream a(committed), b(generated);
  std::string lineA, lineB;
  for (int line = 1;; ++line) {
    const bool moreA = static_cast<bool>(std::getline(a, lineA));
    const bool moreB = static_cast<bool>(std::getline(b, lineB));
    if (!moreA && !moreB) return "texts differ only in line ends";
    if (!moreA) lineA = "(end)";
    if (!moreB) lineB = "(end)";
    if (lineA != lineB || !moreA || !moreB)
      return "line " + std::to_string(line) + ":\n  " + nameA + ": " + lineA + "\n  " + nameB +
             ": " + lineB;
  }
}

std::string unescapeXml(std::string text) {
  const std::pair<const char*, const char*> entities[] = {
      {"&#45;", "-"}, {"&gt;", ">"}, {"&lt;", "<"}, {"&quot;", "\""}, {"&#39;", "'"}, {"&amp;", "&"}};
  for (const auto& [entity, plain] : entities)
    for (size_t at; (at = text.find(entity)) != std::string::npos;) text.replace(at, std::strlen(entity), plain);
  return text;
}

// What a drawing shows of the graph, one entry per node and edge, sorted: its kind, its
// title (node name, or "producer->consumer"), its label and whether it is bold or dashed.
using Drawing = std::vector<std::string>;

// From the dot text Pipeline::dot() writes: `"a" [label="a", style=bold];` and
// `"a" -> "b" [label="x, y : z", style=dashed];`.
Drawing drawingOfDot(const std::string& dot) {
  Drawing drawing;
  const std::regex node(R"re(^\s*"([^"]+)" \[label="([^"]*)"(, style=bold)?\];$)re");
  const std::regex edge(R"re(^\s*"([^"]+)" -> "([^"]+)" \[label="([^"]*)"(, style=dashed)?\];$)re");
  std::istringstream lines(dot);
  for (std::string line; std::getline(lines, line);) {
    std::smatch m;
    if (std::regex_match(line, m, node))
      drawing.push_back("node " + m[1].str() + " | " + m[2].str() + (m[3].matched ? " | bold" : ""));
    else if (std::regex_match(line, m, edge))
      drawing.push_back("edge " + m[1].str() + "->" + m[2].str() + " | " + m[3].str() +
                        (m[4].matched ? " | dashed" : ""));
  }
  std::sort(drawing.begin(), drawing.end());
  return drawing;
}

// From Graphviz's SVG: each `<g class="node|edge">` has a <title>, the label as <text>, and
// draws bold as stroke-width="2", dashed as stroke-dasharray. Coordinates are left out (they
// differ between Graphviz versions).
Drawing drawingOfSvg(const std::string& svg) {
  Drawing drawing;
  const std::regex group(R"re(<g id="[^"]*" class="(node|edge)">([\s\S]*?)</g>)re");
  const std::regex title(R"re(<title>([^<]*)</title>)re");
  const std::regex text(R"re(<text[^>]*>([^<]*)</text>)re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), group); it != std::sregex_iterator(); ++it) {
    const std::string kind = (*it)[1].str(), body = (*it)[2].str();
    std::smatch m;
    std::string entry = kind + " ";
    if (std::regex_search(body, m, title)) entry += unescapeXml(m[1].str());
    std::string label;
    for (auto t = std::sregex_iterator(body.begin(), body.end(), text); t != std::sregex_iterator(); ++t)
      label += (label.empty() ? std::string() : " ") + unescapeXml((*t)[1].str());
    entry += " | " + label;
    if (kind == "node" && body.find("stroke-width=\"2\"") != std::string::npos) entry += " | bold";
    if (kind == "edge" && body.find("stroke-dasharray") != std::string::npos) entry += " | dashed";
    drawing.push_back(entry);
  }
  std::sort(drawing.begin(), drawing.end());
  return drawing;
}

std::string joinedLines(const Drawing& drawing) {
  std::string text;
  for (const std::string& entry : drawing) text += entry + "\n";
  return text;
}

TEST(StageDocs, ReadmeTableIsTheDeclarations) {
  const std::string readme = readSourceFile("README.md");
  const std::string begin = "<!-- stage-table:begin -->\n", end = "<!-- stage-table:end -->";
  const size_t from = readme.find(begin), to = readme.find(end);
  ASSERT_NE(from, std::string::npos) << "README.md has no line " << begin;
  ASSERT_NE(to, std::string::npos) << "README.md has no line " << end;
  ASSERT_LT(from, to);
  EXPECT_EQ(readme.find(begin, from + 1), std::string::npos) << "two begin markers in README.md";
  const std::string committed = readme.substr(from + begin.size(), to - from - begin.size());
  const std::string generated = stageTableMarkdown(Pipeline());
  EXPECT_TRUE(committed == generated)
      << "README.md's stage table differs from the stage declarations; " << kRefresh << ".\n"
      << firstDifference(committed, generated);
}

TEST(StageDocs, GraphDotIsTheRegistry) {
  const std::string committed = readSourceFile("docs/stage_graph.dot");
  const std::string generated = Pipeline().dot();
  EXPECT_TRUE(committed == generated)
      << "docs/stage_graph.dot differs from `penumbra graph`; " << kRefresh << ".\n"
      << firstDifference(committed, generated);
}

TEST(StageDocs, SvgDrawsTheCommittedDot) {
  const Drawing expected = drawingOfDot(readSourceFile("docs/stage_graph.dot"));
  const Drawing drawn = drawingOfSvg(readSourceFile("docs/stage_graph.svg"));
  // The dot has every stage as a node and at least one edge per stage but the first.
  const size_t stages = Pipeline().stages().size();
  ASSERT_GE(expected.size(), 2 * stages - 1) << "the dot text was not parsed";
  EXPECT_TRUE(expected == drawn)
      << "docs/stage_graph.svg is not drawn from docs/stage_graph.dot; " << kRefresh << ".\n"
      << firstDifference(joinedLines(drawn), joinedLines(expected), "svg", "dot");
}

TEST(StageDocs, SvgParserSeesAChange) {
  // The comparison above could pass by parsing nothing from either side: a changed label and
  // a dropped edge must show.
  const std::string dot = readSourceFile("docs/stage_graph.dot");
  const std::string svg = readSourceFile("docs/stage_graph.svg");
  ASSERT_FALSE(drawingOfSvg(svg).empty());
  std::string relabelled = svg;
  const size_t at = relabelled.find(">light_layers</text>");
  ASSERT_NE(at, std::string::npos);
  relabelled.replace(at, 13, ">light_layer_");
  EXPECT_NE(drawingOfSvg(relabelled), drawingOfDot(dot));
  std::string fewer = dot;
  const size_t edge = fewer.find(" -> ");
  ASSERT_NE(edge, std::string::npos);
  const size_t lineStart = fewer.rfind('\n', edge) + 1;
  fewer.erase(lineStart, fewer.find('\n', edge) + 1 - lineStart);
  EXPECT_NE(drawingOfDot(fewer), drawingOfSvg(svg));
}

TEST(StageDocs, EveryStageNamesItsSourceAndSummary) {
  // The table's source and summary columns come from these declarations.
  const Pipeline pipeline;
  for (const auto& stage : pipeline.stages()) {
    EXPECT_FALSE(stage->thesisSection().empty()) << stage->name() << " names no source";
    EXPECT_FALSE(stage->summary().empty()) << stage->name() << " has no summary";
    EXPECT_FALSE(stage->outputs().empty()) << stage->name() << " declares no output";
  }
}

// Each stage has a short README in its own folder, stages/<family>/<stage>/README.md, naming
// its paper section and every input slot and output it declares (a renamed or added slot
// fails here until the README says so).
TEST(StageDocs, EveryStageHasAReadmeNamingItsSlotsAndOutputs) {
  namespace fs = std::filesystem;
  const fs::path stages = fs::path(PENUMBRA_SOURCE_DIR) / "stages";
  const Pipeline pipeline;
  for (const auto& stage : pipeline.stages()) {
    std::vector<fs::path> found;
    for (const auto& family : fs::directory_iterator(stages))
      if (family.is_directory() && fs::exists(family.path() / stage->name() / "README.md"))
        found.push_back(family.path() / stage->name() / "README.md");
    ASSERT_EQ(found.size(), 1u) << stage->name() << ": expected one stages/<family>/" << stage->name()
                                << "/README.md";
    const std::string readme = readSourceFile(fs::relative(found[0], PENUMBRA_SOURCE_DIR).string());
    const std::string where = fs::relative(found[0], PENUMBRA_SOURCE_DIR).string();
    EXPECT_NE(readme.find(stage->thesisSection()), std::string::npos) << where << ": names no " << stage->thesisSection();
    for (const Input& input : stage->inputs())
      EXPECT_NE(readme.find("`" + input.name + "`"), std::string::npos) << where << ": no input `" << input.name << "`";
    for (const Output& output : stage->outputs())
      EXPECT_NE(readme.find("`" + output.name + "`"), std::string::npos) << where << ": no output `" << output.name << "`";
    EXPECT_NE(readme.find("## Numbers"), std::string::npos) << where << ": no numbers";
  }
}

}  // namespace
