// raster4d views: per FB pixel, the triangles and samples its lists hold and the pairs its
// STEP 5 tested with the four planes (after the early rejection, when it is on).
#include "raster4d.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, r32f) uniform writeonly image2D trianglesImage;
layout(binding = 1, r32f) uniform writeonly image2D samplesImage;
layout(binding = 2, r32f) uniform writeonly image2D pairsImage;
layout(std430, binding = R4D_CELLS_TRIANGLE_COUNTS) readonly buffer TriangleCounts { uint triangleCounts[]; };
layout(std430, binding = R4D_CELLS_SAMPLE_COUNTS) readonly buffer SampleCounts { uint sampleCounts[]; };
layout(std430, binding = R4D_CELLS_PAIRS) readonly buffer CellPairs { uvec4 cellPairs[]; };

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (cell.x >= r4d.sizes.x || cell.y >= r4d.sizes.y) return;
  uint index = uint(cell.y * r4d.sizes.x + cell.x);
  imageStore(trianglesImage, cell, vec4(float(triangleCounts[index])));
  imageStore(samplesImage, cell, vec4(float(sampleCounts[index])));
  imageStore(pairsImage, cell, vec4(float(cellPairs[index].y)));
}
