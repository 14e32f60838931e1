// raster4d STEP 5 (Algorithm 3): per FB pixel, every (sample, triangle) pair of its two
// lists; one invocation per sample entry of the current band and chunk of the triangles of
// the entry's pixel (the chunk: the group's z, from uChunkBase), looping over that chunk.
// SAMPLES (m, defined when the program is built) light rows.
//  1. Early rejection (lines 5-6): the sample's Proj4 must lie inside the triangle's AABB,
//     else the triangle hides no point of the light from it (full coverage, Appendix).
//  2. Four planes (lines 7-10): the three through the sample and an edge (inside: the
//     side of the opposite vertex; a light sample inside all three is in the cone from the
//     sample through the triangle) and the triangle's plane (the light sample must be
//     strictly on the other side from the output sample).
//  3. Row masks (lines 11-17): each plane keeps a prefix or a suffix of each light row
//     (raster4d.glsl rowInside); or, with row masks off, every sample tested alone.
#include "raster4d.glsl"
layout(local_size_x = 64) in;
layout(std430, binding = R4D_OCCLUSION_RECEIVERS) readonly buffer Receivers { vec4 receivers[]; };
layout(std430, binding = R4D_OCCLUSION_LS_TRIANGLES) readonly buffer LsTriangles { vec4 lsVertices[]; };
layout(std430, binding = R4D_OCCLUSION_BOXES) readonly buffer Boxes { vec4 boxes[]; };
layout(std430, binding = R4D_OCCLUSION_SAMPLE_LIST) readonly buffer SampleList { uvec2 sampleEntries[]; };
layout(std430, binding = R4D_OCCLUSION_TRIANGLE_STARTS) readonly buffer TriangleStarts { uint triangleStarts[]; };
layout(std430, binding = R4D_OCCLUSION_TRIANGLE_LIST) readonly buffer TriangleList { uint triangleEntries[]; };
layout(std430, binding = R4D_OCCLUSION_MASKS) buffer Masks { uint masks[]; };
layout(std430, binding = R4D_OCCLUSION_CELL_PAIRS) buffer CellPairs { uint cellPairs[]; };  // 4 per FB pixel
layout(location = R4D_OCCLUSION_CHUNK_BASE_LOCATION) uniform int uChunkBase;

const int kWords = (SAMPLES + 31) / 32;

bool insideAll(LightPlane planes[4], int row, int column) {  // no loop (rowInside)
  return planeInside(rowStart(planes[0], row), planes[0].step, column, planes[0].strict) &&
         planeInside(rowStart(planes[1], row), planes[1].step, column, planes[1].strict) &&
         planeInside(rowStart(planes[2], row), planes[2].step, column, planes[2].strict) &&
         planeInside(rowStart(planes[3], row), planes[3].step, column, planes[3].strict);
}

uvec2 rowOccluded(LightPlane planes[4], int row) {
  if (r4d.modes.z == 0) {  // per-sample tests (Table 2's baseline for the row speed-up)
    uvec2 bits = uvec2(0u);
    for (int column = 0; column < SAMPLES; ++column)
      if (insideAll(planes, row, column)) bits[column >> 5] |= 1u << uint(column & 31);
    return bits;
  }
  uvec2 bits = rowInside(rowStart(planes[0], row), planes[0].step, SAMPLES, planes[0].strict);
  if (bits != uvec2(0u)) bits &= rowInside(rowStart(planes[1], row), planes[1].step, SAMPLES, planes[1].strict);
  if (bits != uvec2(0u)) bits &= rowInside(rowStart(planes[2], row), planes[2].step, SAMPLES, planes[2].strict);
  if (bits != uvec2(0u)) bits &= rowInside(rowStart(planes[3], row), planes[3].step, SAMPLES, planes[3].strict);
  return bits;
}

// The pair's four planes (2.) and rows (3.), ORed into `mask`; whether any bit was set.
bool pairOccludes(vec3 q, uint triangle, inout uvec2 mask[SAMPLES]) {
  vec3 v0 = lsVertices[3u * triangle].xyz, v1 = lsVertices[3u * triangle + 1u].xyz,
       v2 = lsVertices[3u * triangle + 2u].xyz;
  vec3 e0 = v0 - q, e1 = v1 - q, e2 = v2 - q;
  vec3 triangleNormal = cross(v1 - v0, v2 - v0);
  float orientation = dot(cross(e0, e1), e2);
  float side = dot(triangleNormal, q - v0);
  if (orientation == 0.0 || side == 0.0) return false;  // the sample is in the triangle's plane
  LightPlane planes[4];
  planes[0] = lightPlane(cross(e0, e1), q, sign(orientation), false);
  planes[1] = lightPlane(cross(e1, e2), q, sign(orientation), false);
  planes[2] = lightPlane(cross(e2, e0), q, sign(orientation), false);
  planes[3] = lightPlane(triangleNormal, v0, -sign(side), true);
  // Row culling (our addition, raster4d.row_culling): when every vertex is nearer the light
  // than the sample, the cone from the sample through the triangle meets the light plane in
  // the triangle of the vertices' projections from the sample; rows outside its y extent
  // (one row of margin against round-off) have no bit.
  int firstRow = 0, lastRow = SAMPLES - 1;
  if (r4d.options.x != 0 && max(v0.z, max(v1.z, v2.z)) < q.z) {
    vec3 lsY = vec3(v0.y, v1.y, v2.y), lsZ = vec3(v0.z, v1.z, v2.z);
    vec3 lightY = q.y + (lsY - q.y) * (q.z / (q.z - lsZ));
    float lo = (min(lightY.x, min(lightY.y, lightY.z)) + r4d.light.y) / r4d.light.w;
    float hi = (max(lightY.x, max(lightY.y, lightY.z)) + r4d.light.y) / r4d.light.w;
    if (lo >= -1.0e6 && hi <= 1.0e6) {  // false for NaN or overflow: keep every row
      firstRow = int(clamp(floor(lo) - 1.0, 0.0, float(SAMPLES - 1)));
      lastRow = int(clamp(ceil(hi) + 1.0, 0.0, float(SAMPLES - 1)));
    }
  }
  bool occludes = false;
  for (int row = firstRow; row <= lastRow; ++row) {
    uvec2 bits = rowOccluded(planes, row);
    mask[row] |= bits;
    occludes = occludes || bits != uvec2(0u);
  }
  return occludes;
}

void main() {
  uint entry = linearIndex();
  if (entry >= uint(r4d.dispatch.x)) return;
  uvec2 sampleEntry = sampleEntries[entry];  // (eye pixel, FB pixel)
  vec3 q = receivers[sampleEntry.x].xyz;
  vec4 qBox = proj4(q);
  // This invocation's chunk of the pixel's triangle list (dispatch.w entries each): long
  // lists are split so that each invocation's loop stays under a driver's per-invocation
  // loop limit (raster4d.glsl); the chunks are ORed into the same mask.
  uint listFirst = triangleStarts[sampleEntry.y] - uint(r4d.band.w);
  uint listEnd = triangleStarts[sampleEntry.y + 1u] - uint(r4d.band.w);
  uint chunk = uint(uChunkBase) + gl_WorkGroupID.z;
  uint first = min(listFirst + chunk * uint(r4d.dispatch.w), listEnd);
  uint end = min(first + uint(r4d.dispatch.w), listEnd);
  if (first == end) return;
  uvec2 mask[SAMPLES];
  for (int row = 0; row < SAMPLES; ++row) mask[row] = uvec2(0u);
  uint kept = 0u, occluding = 0u;
  for (uint k = first; k < end; ++k) {
    uint triangle = triangleEntries[k];
    vec4 box = boxes[triangle];
    bool rejected = r4d.modes.y != 0 &&  // 1.
                    (any(lessThan(qBox.xy, box.xy)) || any(greaterThan(qBox.zw, box.zw)));
    if (!rejected) {
      ++kept;
      if (pairOccludes(q, triangle, mask)) ++occluding;
    }
  }
  uint base = sampleEntry.x * uint(SAMPLES * kWords);
  for (int row = 0; row < SAMPLES; ++row)
    for (int word = 0; word < kWords; ++word)
      if (mask[row][word] != 0u) atomicOr(masks[base + uint(row * kWords + word)], mask[row][word]);
  atomicAdd(cellPairs[4u * sampleEntry.y], end - first);
  atomicAdd(cellPairs[4u * sampleEntry.y + 1u], kept);
  atomicAdd(cellPairs[4u * sampleEntry.y + 2u], occluding);
}
