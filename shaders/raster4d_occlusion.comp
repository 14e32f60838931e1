// raster4d STEP 5 (Algorithm 3): per FB pixel, every (sample, triangle) pair of its two
// lists; one invocation per sample entry of the current band, looping over the triangles
// of the entry's pixel. SAMPLES (m, defined when the program is built) light rows.
//  1. Early rejection (lines 5-6): the sample's Proj4 must lie inside the triangle's AABB,
//     else the triangle hides no point of the light from it (full coverage, Appendix).
//  2. Four planes (lines 7-10): the three through the sample and an edge (inside: the
//     side of the opposite vertex; a light sample inside all three is in the cone from the
//     sample through the triangle) and the triangle's plane (the light sample must be
//     strictly on the other side from the output sample).
//  3. Row masks (lines 11-17): each plane keeps a prefix or a suffix of each light row
//     (shared/raster4d.glsl rowInside); or, with row masks off, every sample tested alone.
#include "shared/raster4d.glsl"
layout(local_size_x = 64) in;
layout(std430, binding = RASTER4D_RECEIVERS_BINDING) readonly buffer Receivers { vec4 receivers[]; };
layout(std430, binding = RASTER4D_LS_TRIANGLES_BINDING) readonly buffer LsTriangles { vec4 lsVertices[]; };
layout(std430, binding = RASTER4D_TRIANGLE_BOXES_BINDING) readonly buffer Boxes { vec4 boxes[]; };
layout(std430, binding = RASTER4D_SAMPLE_LIST_BINDING) readonly buffer SampleList { uvec2 sampleEntries[]; };
layout(std430, binding = RASTER4D_TRIANGLE_STARTS_BINDING) readonly buffer TriangleStarts { uint triangleStarts[]; };
layout(std430, binding = RASTER4D_TRIANGLE_LIST_BINDING) readonly buffer TriangleList { uint triangleEntries[]; };
layout(std430, binding = RASTER4D_MASKS_BINDING) buffer Masks { uint masks[]; };
layout(std430, binding = RASTER4D_CELL_PAIRS_BINDING) buffer CellPairs { uvec4 cellPairs[]; };

const int kWords = (SAMPLES + 31) / 32;

bool insideAll(LightPlane planes[4], int row, int column) {
  for (int k = 0; k < 4; ++k)
    if (!planeInside(rowStart(planes[k], row), planes[k].step, column, planes[k].strict))
      return false;
  return true;
}

uvec2 rowOccluded(LightPlane planes[4], int row) {
  if (r4d.modes.z == 0) {  // per-sample tests (Table 2's baseline for the row speed-up)
    uvec2 bits = uvec2(0u);
    for (int column = 0; column < SAMPLES; ++column)
      if (insideAll(planes, row, column)) bits[column >> 5] |= 1u << uint(column & 31);
    return bits;
  }
  uvec2 bits = prefixBits(SAMPLES);
  for (int k = 0; k < 4 && bits != uvec2(0u); ++k)
    bits &= rowInside(rowStart(planes[k], row), planes[k].step, SAMPLES, planes[k].strict);
  return bits;
}

void main() {
  uint entry = linearIndex();
  if (entry >= uint(r4d.dispatch.x)) return;
  uvec2 sampleEntry = sampleEntries[entry];  // (eye pixel, FB pixel)
  vec3 q = receivers[sampleEntry.x].xyz;
  vec4 qBox = proj4(q);
  uint first = triangleStarts[sampleEntry.y] - uint(r4d.band.w);
  uint end = triangleStarts[sampleEntry.y + 1u] - uint(r4d.band.w);
  uvec2 mask[SAMPLES];
  for (int row = 0; row < SAMPLES; ++row) mask[row] = uvec2(0u);
  uint kept = 0u, occluding = 0u;
  for (uint k = first; k < end; ++k) {
    uint triangle = triangleEntries[k];
    vec4 box = boxes[triangle];
    if (r4d.modes.y != 0 && (any(lessThan(qBox.xy, box.xy)) || any(greaterThan(qBox.zw, box.zw))))
      continue;  // 1.
    ++kept;
    vec3 v0 = lsVertices[3u * triangle].xyz, v1 = lsVertices[3u * triangle + 1u].xyz,
         v2 = lsVertices[3u * triangle + 2u].xyz;
    vec3 e0 = v0 - q, e1 = v1 - q, e2 = v2 - q;
    vec3 triangleNormal = cross(v1 - v0, v2 - v0);
    float orientation = dot(cross(e0, e1), e2);
    float side = dot(triangleNormal, q - v0);
    if (orientation == 0.0 || side == 0.0) continue;  // the sample is in the triangle's plane
    LightPlane planes[4];  // 2.
    planes[0] = lightPlane(cross(e0, e1), q, sign(orientation), false);
    planes[1] = lightPlane(cross(e1, e2), q, sign(orientation), false);
    planes[2] = lightPlane(cross(e2, e0), q, sign(orientation), false);
    planes[3] = lightPlane(triangleNormal, v0, -sign(side), true);
    bool occludes = false;
    for (int row = 0; row < SAMPLES; ++row) {  // 3.
      uvec2 bits = rowOccluded(planes, row);
      mask[row] |= bits;
      occludes = occludes || bits != uvec2(0u);
    }
    if (occludes) ++occluding;
  }
  uint base = sampleEntry.x * uint(SAMPLES * kWords);
  for (int row = 0; row < SAMPLES; ++row)
    for (int word = 0; word < kWords; ++word)
      if (mask[row][word] != 0u) atomicOr(masks[base + uint(row * kWords + word)], mask[row][word]);
  atomicAdd(cellPairs[sampleEntry.y].x, end - first);
  atomicAdd(cellPairs[sampleEntry.y].y, kept);
  atomicAdd(cellPairs[sampleEntry.y].z, occluding);
}
