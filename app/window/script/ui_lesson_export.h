// A lesson's figures (docs/lessons.md): where they go, the numbers its
// texts quote from the run, each exported panel with its caption, and at the end the figure
// sheet (app/figures/figure_sheet.h) and lesson.md (the title, every "say" as played, the
// panels and their captions).
//
// Where: `--export DIR` wins; else a lesson's {"export_dir": "name"} is a folder under the
// program's output folder (kDefaultExportDirectory); else the lesson's file name there
// (lessons/fig_3_3.json -> penumbra_exports/fig_3_3). Never the working directory itself.
//
// Numbers: a "say" text or a caption may hold {ms:stage} (that stage's median time over the
// runs with the current settings; stages joined by '+' are summed), {ms} (the pipeline's
// median) and {counter} (frame.counters, e.g. {error.rmse}); they are filled in when the
// action runs; "keep" stores one under a name for a later text. An unknown name stops the lesson (it would otherwise print a wrong number).
#pragma once
#include <nlohmann/json.hpp>
#include <string>

#include "window/script/ui_script_actions.h"

class UiState;

// The folder a lesson exports into when no --export and no export_dir name one.
std::string defaultLessonDirectory(const std::string& lessonPath);
// {"export_dir": ...}: a relative folder name without "..". "" or what was expected.
std::string checkExportDirName(const nlohmann::json& value);
// {"export_view": "f.png" | "dir" | {"file": "f.png", "caption": "...", "annotate": true}}
std::string checkExportView(const nlohmann::json& value);

// Replaces {ms:...}, {ms}, {counter} and kept names by the numbers; "" in `problem` or why not.
std::string fillNumbers(const UiState& state, const ScriptContext& context, const std::string& text,
                        std::string& problem);
// {"keep": {"rmse_random": "error.rmse", "t_trace": "ms:trace"}}: this run's numbers, kept
// under a name for a later text ("{rmse_random}").
std::string keepNumbers(const UiState& state, const nlohmann::json& a, ScriptContext& context);
// The export_view handler: exports (a PNG with its EXR beside it), and records the PNG as a
// panel of the lesson.
std::string exportView(UiState& state, const nlohmann::json& a, ScriptContext& context);
// {"screenshot": "f.png" | {"file": "f.png", "caption": "...", "crop": "view" | "view:N" | "window:NAME"}}:
// the window, also a panel; on the sheet only the active view's image region ("view"), view
// N's ("view:0" is A) or the named ImGui window ("window:Ray trace of the picked pixel").
std::string checkScreenshot(const nlohmann::json& value);
std::string screenshot(const UiState& state, const nlohmann::json& a, ScriptContext& context);
// At the end of a lesson with panels: figure_sheet.png/.pdf and lesson.md. "" or why not.
std::string finishLesson(const ScriptContext& context);
