#include "io/image_export.h"

#include <OpenImageIO/imageio.h>

#include <cerrno>
#include <cstring>
#include <cstdio>
#include <stdexcept>

#include "io/colormap.h"
#include "io/output_path.h"

namespace {

// "dir/name.exr" -> "dir/.name.partial-<pid>.exr": same extension, so OIIO picks the same
// writer; a killed run's leftover is removed by the next check of the same output.
std::filesystem::path temporaryName(const std::filesystem::path& path) {
  return temporaryFileName(path);
}

void writeImage(const std::filesystem::path& path, const OIIO::ImageSpec& spec,
                OIIO::TypeDesc type, const void* topRowFirst) {
  const auto temporary = temporaryName(path);
  auto out = OIIO::ImageOutput::create(path.string());
  if (!out) throw std::runtime_error("cannot write " + path.string() + ": " + OIIO::geterror());
  errno = 0;
  if (!out->open(temporary.string(), spec) || !out->write_image(type, topRowFirst) ||
      !out->close()) {
    const int saved = errno;
    const std::string reason = out->geterror();
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw WriteError(writeFailure(path, saved, reason));
  }
  std::filesystem::rename(temporary, path);
}

}  // namespace

void writeExr(const std::filesystem::path& path, const std::vector<float>& values, int width,
              int height, const std::vector<std::string>& channelNames) {
  const int channels = int(channelNames.size());
  std::vector<float> flipped(values.size());
  const size_t row = size_t(width) * channels;
  for (int y = 0; y < height; ++y)
    std::copy_n(&values[size_t(height - 1 - y) * row], row, &flipped[size_t(y) * row]);
  OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::FLOAT);
  spec.channelnames = channelNames;
  spec.alpha_channel = -1;  // raw data: no channel is treated as alpha
  spec.attribute("compression", "zip");
  writeImage(path, spec, OIIO::TypeDesc::FLOAT, flipped.data());
}

void writePng(const std::filesystem::path& path, const std::vector<std::uint8_t>& rgb,
              int width, int height) {
  OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:UnassociatedAlpha", 1);
  writeImage(path, spec, OIIO::TypeDesc::UINT8, rgb.data());
}

std::vector<float> readExr(const std::filesystem::path& path, int& width, int& height,
                           std::vector<std::string>& channelNames) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) throw std::runtime_error("cannot read " + path.string() + ": " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  width = spec.width;
  height = spec.height;
  channelNames = spec.channelnames;
  std::vector<float> topRowFirst(size_t(width) * height * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, topRowFirst.data()))
    throw std::runtime_error("cannot read " + path.string() + ": " + in->geterror());
  std::vector<float> values(topRowFirst.size());
  const size_t row = size_t(width) * spec.nchannels;
  for (int y = 0; y < height; ++y)
    std::copy_n(&topRowFirst[size_t(height - 1 - y) * row], row, &values[size_t(y) * row]);
  return values;
}

std::vector<std::filesystem::path> exportTexture(const std::filesystem::path& directory,
                                                 const std::string& stem,
                                                 const GlTexture& texture, const Output& output,
                                                 int layer) {
  const std::vector<float> values = texture.readFloats(layer);
  const auto exr = directory / (stem + ".exr");
  const auto png = directory / (stem + ".png");
  writeExr(exr, values, texture.width(), texture.height(), output.channels);
  // The PNG as a view first shows it: errors and counts in the range of their data
  // (applyDataRange, io/colormap.h), everything else in its declared range.
  DisplayHint hint = output.display;
  applyDataRange(hint, values, texture.channelCount());
  writePng(png, displayRgb8(values, texture.width(), texture.height(), texture.channelCount(), hint),
           texture.width(), texture.height());
  return {exr, png};
}

void writeTextFile(const std::filesystem::path& path, const std::string& text) {
  const auto temporary = temporaryName(path);
  std::FILE* out = std::fopen(temporary.c_str(), "wb");
  if (!out) throw WriteError(writeFailure(path, errno, ""));
  errno = 0;
  bool ok = std::fwrite(text.data(), 1, text.size(), out) == text.size();
  ok = std::fflush(out) == 0 && ok;
  int saved = errno;
  if (std::fclose(out) != 0 && ok) {
    ok = false;
    saved = errno;
  }
  if (!ok) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw WriteError(writeFailure(path, saved, ""));
  }
  std::filesystem::rename(temporary, path);
}
