// Writing stage outputs (docs/design.md#exports): EXR with raw float values and named channels, PNG
// as a view displays them. Every file is written under a temporary name and renamed.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "gl/gl_texture.h"
#include "core/stage.h"

// Raw floats (GL order, bottom row first) -> EXR, top row first, float channels.
void writeExr(const std::filesystem::path& path, const std::vector<float>& values, int width,
              int height, const std::vector<std::string>& channelNames);
void writePng(const std::filesystem::path& path, const std::vector<std::uint8_t>& rgb,
              int width, int height);
// Reads an EXR back into GL order (for tests and tools).
std::vector<float> readExr(const std::filesystem::path& path, int& width, int& height,
                           std::vector<std::string>& channelNames);

// Writes `<dir>/<stem>.exr` and `<dir>/<stem>.png` for one texture layer; returns the paths.
std::vector<std::filesystem::path> exportTexture(const std::filesystem::path& directory,
                                                 const std::string& stem,
                                                 const GlTexture& texture, const Output& output,
                                                 int layer = 0);
// Writes text atomically.
void writeTextFile(const std::filesystem::path& path, const std::string& text);
