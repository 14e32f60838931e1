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

void checkCapabilities(const Stage& stage) {
  auto fail = [&](const char* capability, const std::string& missing) {
    throw std::invalid_argument("stage '" + stage.name() + "' declares capability " + capability +
                                " but " + missing);
  };
  auto needInt = [&](const char* capability, const char* key) {
    for (const Param& param : stage.params())
      if (param.key == key) {
        if (param.type != Param::Type::Int) fail(capability, std::string("its parameter '") + key + "' is not an integer");
        return;
      }
    fail(capability, std::string("has no parameter '") + key + "'");
  };
  auto needInput = [&](const char* capability, const char* slot) {
    for (const Input& input : stage.inputs())
      if (input.name == slot) return;
    fail(capability, std::string("has no input slot '") + slot + "'");
  };
  if (stage.can(kCapabilityPicksEyePixel)) {
    needInt("PicksEyePixel", kPickXParam);
    needInt("PicksEyePixel", kPickYParam);
  }
  if (stage.can(kCapabilityPicksMapTexel)) {
    needInt("PicksMapTexel", kPatchXParam);
    needInt("PicksMapTexel", kPatchYParam);
    needInt("PicksMapTexel", kMapResolutionParam);
  }
  if (stage.can(kCapabilityRecordsRays)) {
    needInt("RecordsRays", kRecordXParam);
    needInt("RecordsRays", kRecordYParam);
    needInt("RecordsRays", kRaysParam);
    needInput("RecordsRays", "near");
    needInput("RecordsRays", "far");
  }
  if (stage.can(kCapabilityPickedLightMask)) {
    if (!stage.can(kCapabilityPicksEyePixel)) fail("PickedLightMask", "not PicksEyePixel (whose pixel's mask?)");
    bool found = false;
    for (const Output& output : stage.outputs())
      found |= output.name == kPickedLightMaskOutput && !output.isBuffer();
    if (!found) fail("PickedLightMask", std::string("has no texture output '") + kPickedLightMaskOutput + "'");
  }
}
