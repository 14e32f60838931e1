#include "core/stage.h"

#include <stdexcept>

namespace {
template <typename List, typename Name>
auto& findByName(List& list, const std::string& wanted, Name nameOf, const std::string& where) {
  for (auto& item : list)
    if (nameOf(item) == wanted) return item;
  std::string valid;
  for (auto& item : list) valid += (valid.empty() ? "" : ", ") + nameOf(item);
  throw std::out_of_range("unknown " + where + " '" + wanted + "'; valid: " + valid);
}
}  // namespace

Param& Stage::param(const std::string& key) {
  return findByName(params_, key, [](const Param& p) { return p.key; }, name() + " parameter");
}
const Param& Stage::param(const std::string& key) const {
  return findByName(params_, key, [](const Param& p) { return p.key; }, name() + " parameter");
}
const Output& Stage::output(const std::string& wanted) const {
  return findByName(outputs_, wanted, [](const Output& o) { return o.name; }, name() + " output");
}
const Input& Stage::input(const std::string& wanted) const {
  return findByName(inputs_, wanted, [](const Input& i) { return i.name; }, name() + " input");
}

AutoChoice Stage::chooseAuto(const std::string& key, const Frame&) const {
  throw std::logic_error("stage '" + name() + "' declares no auto rule for '" + key + "'");
}
