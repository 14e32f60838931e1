// Stage `hash`: what the random numbers of the trace look like (thesis §3.1, Appendix A).
// Each eye pixel hashes its screen coordinates, seed = (x, y, 0, 0), with the frame key, as
// the trace does for its first ray, and shows the first light sample and the raw bits.
#include "shared/screen_pass.glsl"
#include "shared/hash.glsl"
#include "stages/shared_inputs/hash/hash_layout.h"
layout(binding = HASH_SAMPLES_IMAGE, rg32f) uniform writeonly image2D samplesImage;
layout(binding = HASH_BITS_IMAGE, r32f) uniform writeonly image2D bitsImage;

void main() {
  ivec2 pixel = screenPixel();
  if (pixel.x < 0) return;
  uvec4 h = hashRand(uvec4(uvec2(pixel), 0u, 0u), frame.keys.x, int(light.sampling.x));
  imageStore(samplesImage, pixel, vec4(toUnitSquare(h.xy), 0.0, 0.0));
  // The first word alone, as a gray level in [0,1): structure here is structure in samples.
  imageStore(bitsImage, pixel, vec4(toUnitSquare(h.xx).x));
}
