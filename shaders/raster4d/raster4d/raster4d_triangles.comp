// raster4d STEP 4 (Algorithm 1 lines 12-17): each occluder triangle to every FB pixel that
// the AABB of its vertices' Proj4 rectangles covers, as counts (pass 0, which also stores
// the light-space vertices and the AABB) or into the lists (pass 1, current band only).
// The AABB is grown by a tolerance (plane.y) so that round-off can only add pairs, never
// drop one. A triangle that reaches the light plane has no bounded Proj4: it goes to every
// pixel and is never rejected early. One wholly behind the light plane, or beyond every
// receiver, cannot be on a segment from a receiver to the light and is left out.
#include "raster4d.glsl"
layout(local_size_x = 64) in;
layout(location = 0) uniform int uScatter;
layout(std430, binding = R4D_TRIANGLES_TRIANGLES) readonly buffer Triangles { vec4 wsVertices[]; };
layout(std430, binding = R4D_TRIANGLES_LS_TRIANGLES) buffer LsTriangles { vec4 lsVertices[]; };
layout(std430, binding = R4D_TRIANGLES_BOXES) buffer Boxes { vec4 boxes[]; };
layout(std430, binding = R4D_TRIANGLES_STATE) buffer State { Raster4dState state; };
layout(std430, binding = R4D_TRIANGLES_COUNTS) buffer Counts { uint counts[]; };
layout(std430, binding = R4D_TRIANGLES_STARTS) readonly buffer Starts { uint starts[]; };
layout(std430, binding = R4D_TRIANGLES_CURSORS) buffer Cursors { uint cursors[]; };
layout(std430, binding = R4D_TRIANGLES_LIST) writeonly buffer List { uint entries[]; };

const float kHuge = 3.0e38;
const vec4 kEmpty = vec4(1.0, 1.0, -1.0, -1.0);

vec4 triangleBox(vec3 v0, vec3 v1, vec3 v2) {
  float nearest = min(v0.z, min(v1.z, v2.z));
  float farthest = max(v0.z, max(v1.z, v2.z));
  if (farthest <= 0.0 || nearest > r4d.plane.x) return kEmpty;
  if (nearest <= r4d.plane.w) {
    atomicAdd(state.counts.w, 1u);
    return vec4(-kHuge, -kHuge, kHuge, kHuge);
  }
  vec4 a = proj4(v0), b = proj4(v1), c = proj4(v2);
  vec4 box = vec4(min(a.xy, min(b.xy, c.xy)), max(a.zw, max(b.zw, c.zw)));
  return box + vec4(-r4d.plane.y, -r4d.plane.y, r4d.plane.y, r4d.plane.y);
}

void main() {
  uint triangle = linearIndex();
  if (triangle >= uint(r4d.modes.w)) return;
  if (state.counts.x == 0u) return;  // no receiver: no segment to the light to cross
  vec4 box;
  bool firstWindow = uScatter == 0 && r4d.band.x == 0;
  if (firstWindow) {
    vec3 v[3];
    for (int k = 0; k < 3; ++k) {
      v[k] = lightSpace(wsVertices[3u * triangle + uint(k)].xyz);
      lsVertices[3u * triangle + uint(k)] = vec4(v[k], 0.0);
    }
    box = triangleBox(v[0], v[1], v[2]);
    boxes[triangle] = box;
  } else {
    box = boxes[triangle];
  }
  if (box.x > box.z) return;
  ivec4 range = fbPixelRange(box);
  if (range.x > range.z || range.y > range.w) return;
  if (firstWindow) atomicAdd(state.counts.z, 1u);
  // Only the rows of the current window (the stage keeps rows x columns under a driver's
  // per-invocation loop limit; raster4d.glsl).
  for (int row = max(range.y, r4d.band.x); row < min(range.w + 1, r4d.band.y); ++row)
    for (int column = range.x; column <= range.z; ++column) {
      uint cell = uint(row * r4d.sizes.x + column);
      if (uScatter == 0) {
        atomicAdd(counts[cell], 1u);
      } else {
        entries[starts[cell] - uint(r4d.band.w) + atomicAdd(cursors[cell], 1u)] = triangle;
      }
    }
}
