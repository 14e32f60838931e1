// raster4d: visibility = 1 - popcount(mask) / m^2 per eye pixel (SAMPLES = m). Before the
// count, the light samples behind the receiver's own tangent plane are marked blocked, the
// rule the reference follows (app/reference/reference_trace.h): an opaque surface does not
// see through itself. Also writes the picked pixel's mask over the light: 1 occluded by a
// triangle, 0.5 behind the tangent plane, 0 reaching the light.
#include "raster4d.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D wsPositionTexture;
layout(binding = 1) uniform sampler2D wsNormalTexture;
layout(binding = 0, r32f) uniform writeonly image2D visibilityImage;
layout(binding = 1, r32f) uniform writeonly image2D pickedMaskImage;
layout(std430, binding = R4D_RESOLVE_RECEIVERS) readonly buffer Receivers { vec4 receivers[]; };
layout(std430, binding = R4D_RESOLVE_MASKS) buffer Masks { uint masks[]; };

const int kWords = (SAMPLES + 31) / 32;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (pixel.x >= r4d.sizes.z || pixel.y >= r4d.sizes.w) return;
  uint index = uint(pixel.y * r4d.sizes.z + pixel.x);
  float kind = receivers[index].w;
  if (kind != 1.0) {  // background: 1 (nothing to shade); behind the light plane: unlit
    imageStore(visibilityImage, pixel, vec4(kind == 0.0 ? 1.0 : 0.0));
    return;
  }
  vec3 lsPosition = lightSpace(texelFetch(wsPositionTexture, pixel, 0).xyz);
  vec3 lsNormal = mat3(r4d.lsFromWorld) * texelFetch(wsNormalTexture, pixel, 0).xyz;
  LightPlane tangent = lightPlane(lsNormal, lsPosition, 1.0, true);  // inside: in front
  bool picked = all(equal(pixel, r4d.pick.xy));
  uint base = index * uint(SAMPLES * kWords);
  int occluded = 0;
  for (int row = 0; row < SAMPLES; ++row) {
    uvec2 behind = prefixBits(SAMPLES) & ~rowInside(rowStart(tangent, row), tangent.step, SAMPLES, true);
    for (int word = 0; word < kWords; ++word) {
      uint bits = masks[base + uint(row * kWords + word)];
      masks[base + uint(row * kWords + word)] = bits | behind[word];
      occluded += bitCount(bits | behind[word]);
      if (!picked) continue;
      for (int bit = 0; bit < 32 && word * 32 + bit < SAMPLES; ++bit) {
        float value = ((bits >> uint(bit)) & 1u) != 0u ? 1.0
                      : ((behind[word] >> uint(bit)) & 1u) != 0u ? 0.5 : 0.0;
        imageStore(pickedMaskImage, ivec2(word * 32 + bit, row), vec4(value));
      }
    }
  }
  imageStore(visibilityImage, pixel, vec4(1.0 - float(occluded) / float(SAMPLES * SAMPLES)));
}
