#include "window/script/ui_lesson_numbers.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "io/colormap.h"
#include "window/ui_state.h"
#include "window/views/texture_view.h"

namespace {

constexpr const char* kKinds[] = {"pixels:", "share:", "min:", "max:", "p99:", "pick:"};

std::string kindOf(const std::string& name) {
  for (const char* kind : kKinds)
    if (name.rfind(kind, 0) == 0) return kind;
  return "";
}

// "error.signed<-0.05" -> key, operator, threshold; false when malformed.
bool comparison(const std::string& text, std::string& key, std::string& op, double& threshold) {
  const size_t at = text.find_first_of("<>=");
  if (at == std::string::npos || at == 0) return false;
  key = text.substr(0, at);
  op = text.substr(at, text.size() > at + 1 && text[at + 1] == '=' ? 2 : 1);
  if (op != "<" && op != ">" && op != "<=" && op != ">=" && op != "==") return false;
  const std::string number = text.substr(at + op.size());
  try {
    size_t used = 0;
    threshold = std::stod(number, &used);
    return used == number.size();
  } catch (const std::exception&) {
    return false;
  }
}

bool passes(float v, const std::string& op, double t) {
  if (!std::isfinite(v)) return false;
  return op == "<" ? v < t : op == ">" ? v > t : op == "<=" ? v <= t : op == ">=" ? v >= t : v == t;
}

}  // namespace

bool isOutputNumber(const std::string& name) { return !kindOf(name).empty(); }

bool outputNumber(const UiState& state, const std::string& name, double& value, std::string& problem) {
  const std::string kind = kindOf(name), rest = name.substr(kind.size());
  std::string key = rest, op;
  double threshold = 0;
  const bool counting = kind == "pixels:" || kind == "share:";
  if (counting && !comparison(rest, key, op, threshold)) {
    problem = "{" + name + "}: expected OUTPUT, a comparison (> < >= <= ==) and a number, e.g. {" +
              kind + "error.signed<-0.05}";
    return false;
  }
  const Frame* frame = state.session.frame.get();
  if (!state.session.outputOf(key)) {
    problem = "{" + name + "}: no output '" + key + "' in this pipeline";
    return false;
  }
  if (!frame || !frame->has(key)) {
    problem = "{" + name + "}: '" + key + "' was not written this run (show it in a view first)";
    return false;
  }
  const GlTexture& texture = frame->texture(key);
  const int channels = texture.channelCount();
  if (kind == "pick:") {
    const glm::ivec2 size{texture.width(), texture.height()};
    if (!state.views.pick || state.views.pickSpace != size) {
      problem = "{" + name + "}: no texel of '" + key + "' is picked (a \"pick\" in a view of its size)";
      return false;
    }
    value = readTexel(texture, state.views.pick->x, state.views.pick->y)[0];
    return true;
  }
  const std::vector<float> values = texture.readFloats(0);
  if (counting) {
    size_t count = 0, total = 0;
    for (size_t i = 0; i < values.size(); i += size_t(channels), ++total) count += passes(values[i], op, threshold);
    value = kind == "pixels:" ? double(count) : 100.0 * double(count) / double(std::max<size_t>(total, 1));
    return true;
  }
  if (kind == "p99:") {
    const Output* output = state.session.outputOf(key);
    float low = 0, high = 0;
    if (!robustRange(values, channels, 0, output->display.colormap == Colormap::Diverging, low, high)) {
      problem = "{" + name + "}: '" + key + "' holds no non-zero value";
      return false;
    }
    value = high;
    return true;
  }
  bool any = false;
  for (size_t i = 0; i < values.size(); i += size_t(channels)) {
    if (!std::isfinite(values[i])) continue;
    value = !any ? values[i] : kind == "min:" ? std::min(value, double(values[i])) : std::max(value, double(values[i]));
    any = true;
  }
  if (!any) problem = "{" + name + "}: '" + key + "' holds no finite value";
  return any;
}
