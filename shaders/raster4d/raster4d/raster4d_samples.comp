// raster4d STEP 3: output samples to FB pixels, as counts (pass 0) or into the lists
// (pass 1, only the FB rows of the current band). Algorithm 2: one pixel per sample, its
// projection from the light corner L0 (the full coverage property, Appendix, makes that
// enough); or Algorithm 1 lines 8-11: every pixel its Proj4 covers (the redundancy of
// Table 2, kept as a toggle to measure it).
#include "raster4d.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(location = 0) uniform int uScatter;
layout(std430, binding = R4D_SAMPLES_RECEIVERS) readonly buffer Receivers { vec4 receivers[]; };
layout(std430, binding = R4D_SAMPLES_COUNTS) buffer Counts { uint counts[]; };
layout(std430, binding = R4D_SAMPLES_STARTS) readonly buffer Starts { uint starts[]; };
layout(std430, binding = R4D_SAMPLES_CURSORS) buffer Cursors { uint cursors[]; };
layout(std430, binding = R4D_SAMPLES_LIST) writeonly buffer List { uvec2 entries[]; };

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (pixel.x >= r4d.sizes.z || pixel.y >= r4d.sizes.w) return;
  uint index = uint(pixel.y * r4d.sizes.z + pixel.x);
  vec4 receiver = receivers[index];
  if (receiver.w != 1.0) return;
  ivec4 range;
  if (r4d.modes.x == RASTER4D_ASSIGN_L0) {
    ivec2 cell = clamp(fbPixel(projFromL0(receiver.xyz)), ivec2(0), r4d.sizes.xy - 1);
    range = ivec4(cell, cell);
  } else {
    range = fbPixelRange(proj4(receiver.xyz));
  }
  for (int row = max(range.y, r4d.band.x); row < min(range.w + 1, r4d.band.y); ++row)
    for (int column = range.x; column <= range.z; ++column) {  // current row window only
      uint cell = uint(row * r4d.sizes.x + column);
      if (uScatter == 0) {
        atomicAdd(counts[cell], 1u);
      } else {
        uint slot = starts[cell] - uint(r4d.band.z) + atomicAdd(cursors[cell], 1u);
        entries[slot] = uvec2(index, cell);
      }
    }
}
