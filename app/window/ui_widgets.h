// Small ImGui helpers shared by the panels: the (?) marker, a parameter drawn from its
// declaration, texture format names, and toolbar wrapping.
#pragma once
#include <epoxy/gl.h>

#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/frame.h"
#include "core/param.h"
#include "core/pipeline.h"

// 1. "(?)" after the last item; hovering shows `text`.
void helpMarker(const std::string& text);
// 2. Draws `param` from its declaration (checkbox, slider, combo) with a (?) marker giving
//    its doc and range; returns true when the user changed it. Under `auto` the control
//    shows `autoValue` (what auto chose this frame, autoChosenValue()), greyed and marked
//    "(auto)"; the parameter's own value, set by hand, is kept in `handValues` while auto is
//    on (the caller's state: UiState::PanelMemory) and returns when auto is unticked.
using ParamHandValues = std::map<const Param*, double>;
bool drawParam(Param& param, ParamHandValues& handValues, std::optional<double> autoValue = {});
// 2b. What `auto` chose for parameter `stage`.`param` in `frame` (stages/shared_inputs/light/auto_params.h):
//     the map size, the layers (as the option index) and the rays per side from the frame's
//     AutoSettings; a choice the pipeline decides (Pipeline::decideAutoChoices) holds its
//     choice in its value. Empty when the parameter is not under auto or nothing ran yet.
std::optional<double> autoChosenValue(const std::string& stage, const Param& param, const Frame* frame);
// 2c. The value the control shows: the choice under auto when there is one, else its own.
double shownParamValue(const Param& param, std::optional<double> autoValue);
// 3. "RGBA32F", "R32UI", "DEPTH32F", ...
const char* formatName(GLenum format);
// 4. Continues the current line if an item `width` wide (pixels at UI scale 1) still fits,
//    else starts a new one.
void sameLineIfFits(float width);
// 4b. Pixels at UI scale 1 -> pixels now (the font size over ImGui's default 13).
float uiPixels(float pixelsAtScale1);
// 4c. The width that buttons with these labels take on the rest of a line (each with the
//     item spacing before it): a text field before them gets the rest. Count a help
//     marker as the label "(?)".
float buttonsWidth(std::initializer_list<const char*> labels);
// 4d. SameLine if buttons with these labels still fit on the line, else a new line.
void sameLineIfButtonsFit(std::initializer_list<const char*> labels);
// 4e. A combo box's preview of `name` ("stage.output") that fits a combo `comboWidth` wide:
//     the name itself if it fits, else the stage cut short ("hard_sh...visibility": the
//     output stays whole, so hard_shadow and pcss visibilities stay apart), else the end
//     cut ("hard_shadow.vi..."). Show the full name in the combo's tooltip.
std::string comboPreview(const std::string& name, float comboWidth);
// 4f. Text in pieces that are never split (a channel's name and value, a counter and its
//     number): on one line, two spaces apart, while they fit; a new line before a piece
//     that does not (ImGui's own wrapping breaks after any '.', inside a number).
void textPieces(const std::vector<std::string>& pieces);
// 4g. Greyed text wrapped at the panel's edge (hints, "not run yet").
void hintText(const std::string& text);
// 5. A stage's timing for a tooltip: last run, median and how many runs it covers, or why
//    it did not run.
std::string timingText(const StageTime& time);
