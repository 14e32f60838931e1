#include "window/ui_frame_change.h"

#include <imgui.h>

#include <cstring>
#include <functional>
#include <string_view>

void mixHash(std::uint64_t& hash, std::uint64_t value) {
  hash ^= value + 0x9e3779b97f4a7c15ull + (hash << 6) + (hash >> 2);
}

namespace {

std::uint64_t bytesHash(const void* data, std::size_t bytes) {
  return std::hash<std::string_view>{}(std::string_view(static_cast<const char*>(data), bytes));
}

std::uint64_t floatBits(float value) {
  std::uint32_t bits = 0;
  static_assert(sizeof bits == sizeof value);
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

// Field by field where a struct has padding (ImDrawCmd); vertices and indices are packed.
std::uint64_t drawDataHash(const ImDrawData& data) {
  std::uint64_t hash = 0;
  mixHash(hash, floatBits(data.DisplaySize.x));
  mixHash(hash, floatBits(data.DisplaySize.y));
  mixHash(hash, std::uint64_t(data.CmdListsCount));
  for (int l = 0; l < data.CmdListsCount; ++l) {
    const ImDrawList& list = *data.CmdLists[l];
    mixHash(hash, bytesHash(list.VtxBuffer.Data, size_t(list.VtxBuffer.Size) * sizeof(ImDrawVert)));
    mixHash(hash, bytesHash(list.IdxBuffer.Data, size_t(list.IdxBuffer.Size) * sizeof(ImDrawIdx)));
    for (const ImDrawCmd& cmd : list.CmdBuffer) {
      for (float v : {cmd.ClipRect.x, cmd.ClipRect.y, cmd.ClipRect.z, cmd.ClipRect.w}) mixHash(hash, floatBits(v));
      mixHash(hash, std::uint64_t(reinterpret_cast<std::uintptr_t>(cmd.TextureId)));
      mixHash(hash, cmd.VtxOffset);
      mixHash(hash, cmd.IdxOffset);
      mixHash(hash, cmd.ElemCount);
      mixHash(hash, cmd.UserCallback != nullptr);
    }
  }
  return hash;
}

}  // namespace

bool FrameChange::changed(const ImDrawData& data, std::uint64_t content) {
  std::uint64_t hash = drawDataHash(data);
  mixHash(hash, content);
  if (!force_ && hash == last_) return false;
  last_ = hash;
  force_ = false;
  return true;
}
