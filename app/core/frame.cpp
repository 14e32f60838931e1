#include "core/frame.h"

#include <stdexcept>

GlTexture& Frame::output(const Stage& stage, const std::string& name, int width, int height,
                         int layers) {
  const Output& declared = stage.output(name);  // throws for undeclared outputs
  GlTexture& texture = textures[stage.name() + "." + name];
  if (texture.id() == 0 || texture.width() != width || texture.height() != height ||
      texture.layers() != layers || texture.internalFormat() != declared.format)
    texture = GlTexture(declared.format, width, height, layers);
  return texture;
}

const GlTexture& Frame::input(const std::string& stageDotOutput) const {
  auto found = textures.find(stageDotOutput);
  if (found == textures.end())
    throw std::runtime_error("stage input '" + stageDotOutput +
                             "' has not been written this frame (is its stage before this one?)");
  return found->second;
}
