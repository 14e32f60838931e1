// The README's stage table, written from the stage declarations (app/core/stage.h): one row
// per stage of the graph in execution order, with its source (thesisSection()), its summary
// and its outputs. scripts/stage_docs.sh puts it between the README's stage-table markers;
// tests/core/test_stage_docs.cpp fails when the committed table differs.
#pragma once
#include <string>

class Pipeline;

// Markdown: a header row, a rule and one row per stage; every line ends in '\n'. A shadow
// method's visibility is bold; ground truths, hierarchies and buffers say so in brackets.
std::string stageTableMarkdown(const Pipeline& pipeline);
