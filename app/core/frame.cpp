#include "core/frame.h"

#include <stdexcept>

#include "core/pipeline.h"

GlTexture& Frame::output(const Stage& stage, const std::string& name, int width, int height,
                         int layers, int levels) {
  const Output& declared = stage.output(name);  // throws for undeclared outputs
  if (declared.isBuffer())
    throw std::logic_error(stage.name() + "." + name + " is a buffer output (outputBuffer)");
  GlTexture& texture = textures[stage.name() + "." + name];
  if (texture.id() == 0 || texture.width() != width || texture.height() != height ||
      texture.layers() != layers || texture.levels() != levels ||
      texture.internalFormat() != declared.format)
    texture = GlTexture(declared.format, width, height, layers, levels);
  return texture;
}

GlBuffer& Frame::outputBuffer(const Stage& stage, const std::string& name) {
  if (!stage.output(name).isBuffer())
    throw std::logic_error(stage.name() + "." + name + " is a texture output (output)");
  auto& slot = buffers[stage.name() + "." + name];
  if (!slot) slot = std::make_unique<GlBuffer>();
  return *slot;
}

namespace {
std::string sourceOf(const Frame& frame, const Stage& stage, const std::string& slot) {
  stage.input(slot);  // throws for undeclared slots
  const std::string source = frame.pipeline.source(stage.name(), slot);
  if (source.empty())
    throw std::runtime_error(stage.name() + "." + slot + " is not connected (set to none)");
  return source;
}
}  // namespace

const GlTexture& Frame::input(const Stage& stage, const std::string& slot) const {
  const std::string source = sourceOf(*this, stage, slot);
  auto found = textures.find(source);
  if (found == textures.end())
    throw std::runtime_error("input " + stage.name() + "." + slot + ": its producer '" +
                             source + "' has not written it this run");
  return found->second;
}

const GlBuffer& Frame::inputBuffer(const Stage& stage, const std::string& slot) const {
  const std::string source = sourceOf(*this, stage, slot);
  auto found = buffers.find(source);
  if (found == buffers.end() || !found->second)
    throw std::runtime_error("input " + stage.name() + "." + slot + ": its producer '" +
                             source + "' has not written it this run");
  return *found->second;
}

bool Frame::connected(const Stage& stage, const std::string& slot) const {
  const std::string source = pipeline.source(stage.name(), slot);
  return !source.empty() && (textures.count(source) || buffers.count(source));
}

double Frame::megabytes(const std::string& stageDotOutput) const {
  if (auto texture = textures.find(stageDotOutput); texture != textures.end())
    return double(texture->second.bytes()) / (1024.0 * 1024.0);
  auto buffer = buffers.find(stageDotOutput);
  if (buffer == buffers.end() || !buffer->second) return 0;
  GLint64 size = 0;
  glGetNamedBufferParameteri64v(buffer->second->id(), GL_BUFFER_SIZE, &size);
  return double(size) / (1024.0 * 1024.0);
}

double Frame::megabytes(const Stage& stage) const {
  double total = 0;
  for (const Output& output : stage.outputs()) total += megabytes(stage.name() + "." + output.name);
  return total;
}

const GlTexture& Frame::texture(const std::string& stageDotOutput) const {
  auto found = textures.find(stageDotOutput);
  if (found == textures.end())
    throw std::runtime_error("output '" + stageDotOutput + "' has not been written this run");
  if (partial.count(stageDotOutput))
    throw std::runtime_error("output '" + stageDotOutput + "' was written only where the "
                             "stages after it read it this run (not requested)");
  return found->second;
}

void Frame::finishReadbacks() {
  if (readbacks.empty()) return;
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<Readback> queued = std::move(readbacks);
  readbacks.clear();
  std::vector<unsigned char> bytes;
  for (const Readback& readback : queued) {
    bytes.resize(size_t(readback.bytes));
    if (readback.bytes > 0)
      glGetNamedBufferSubData(readback.buffer, readback.offset, readback.bytes, bytes.data());
    readback.use(bytes, *this);
  }
}
