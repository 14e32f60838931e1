// The value a parameter that allows `auto` stands for this frame: its own, or what
// stages/shared_inputs/light/auto_settings.h chose (lightAutoSettings(frame)). For readers that report settings.
#pragma once
#include <string>

#include "core/param.h"
#include "shared_inputs/light/auto_settings.h"

inline int effectiveRays(const Param& rays, const AutoSettings& chosen) {
  return rays.automatic ? chosen.raysPerSide : rays.asInt();
}
inline int effectiveResolution(const Param& resolution, const AutoSettings& chosen) {
  return resolution.automatic ? chosen.resolution : resolution.asInt();
}
inline std::string effectiveLayers(const Param& layers, const AutoSettings& chosen) {
  return layers.automatic ? layers.options.at(size_t(chosen.layers - 1)) : layers.asEnum();
}
