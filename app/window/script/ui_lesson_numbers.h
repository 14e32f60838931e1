// Numbers a lesson's text reads from an output of the current run (lessons/README.md,
// "Numbers in texts"), so that no count in a lesson's prose is typed in:
//   {pixels:OUTPUT>V}  texels of OUTPUT's first channel compared with V (> < >= <= ==)
//   {share:OUTPUT>V}   the same as a percentage of OUTPUT's texels
//   {min:OUTPUT} {max:OUTPUT}  over its finite values;  {p99:OUTPUT}  the view's auto range
//                      (robustRange, app/io/colormap.h)
//   {pick:OUTPUT}      its value at the picked texel (the pick must lie in a texture of its size)
// OUTPUT is "stage.output" (layer 0). An output not written this run, a pick elsewhere or a
// malformed comparison is refused with a message naming it.
#pragma once
#include <string>

class UiState;

bool isOutputNumber(const std::string& name);
bool outputNumber(const UiState& state, const std::string& name, double& value, std::string& problem);
