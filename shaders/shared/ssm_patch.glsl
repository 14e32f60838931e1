// Soft shadow maps (Atty et al. 2006): the geometry of one micro-patch, in light view space.
// Light view space: x along the light's right, y along its up, z = distance along the light
// axis from the projection point (Eq 3.1 of the thesis; light_block.h). The light rectangle
// lies in the plane z = zLight (the light depth) with half-size lightHalf; the maps are the
// frustum through it, so map uv (0..1) <-> x / z in [-tanHalfFov.x, +tanHalfFov.x].
// Pure functions (no blocks), so tests/stages/test_ssm_patch.cpp can run them on any input.

// §3.2 (Fig. 4): a texel of the occluder map becomes a micro-patch, a rectangle parallel to
// the light at the texel's depth covering the texel's footprint. The light and the map have
// the same aspect ratio, so every micro-patch has the light's aspect ratio too.
struct MicroPatch {
  vec2 lsMin, lsMax;  // x, y extent at depth z
  float z;
};

MicroPatch microPatchOfTexel(ivec2 texel, vec2 mapSize, float z, vec2 tanHalfFov) {
  vec2 ndcMin = vec2(texel) / mapSize * 2.0 - 1.0;
  vec2 ndcMax = vec2(texel + 1) / mapSize * 2.0 - 1.0;
  return MicroPatch(ndcMin * tanHalfFov * z, ndcMax * tanHalfFov * z, z);
}

// §3.3 (Fig. 5-8): the penumbra extent of a micro-patch is a rectangular pyramid whose edges
// run from each light edge through the opposite patch edge. With depths measured from the
// light plane (z' = z - zLight) and the light centre at the origin:
//   apex O = r C_P at depth r z'_P,  r = LL' / (LL' + PP')   (similar triangles, Fig. 6: the
//     text's "OC_L / OC_P = LL' / PP'"; r is the same on both axes, the aspect ratios agree);
//   its cross-section at depth z' (the "virtual plane" of Fig. 7-8): centre C_P z' / z'_P,
//     half-size (LL' / 2) (z' - z'_O) / z'_O.
// Returns (min.xy, max.xy) of that rectangle at view depth z (z >= the patch's depth).
vec4 penumbraRectAt(MicroPatch micro, vec2 lightHalf, float zLight, float z) {
  vec2 lightSize = 2.0 * lightHalf, patchSize = micro.lsMax - micro.lsMin;
  vec2 r = lightSize / (lightSize + patchSize);
  float zPatch = micro.z - zLight, zPlane = z - zLight;
  vec2 zApex = r * zPatch;
  vec2 centre = 0.5 * (micro.lsMin + micro.lsMax) * (zPlane / zPatch);
  vec2 halfSize = lightHalf * (zPlane - zApex) / zApex;
  return vec4(centre - halfSize, centre + halfSize);
}

// §3.4 (Fig. 9): the fraction of the light's area that the micro-patch hides from the
// receiver point lsReceiver. Back-projecting the patch from the receiver onto the light
// plane scales it about the receiver by (zR - zLight) / (zR - zPatch); in light
// coordinates normalized to [0,1]^2 the clipped area is a product of two interval overlaps,
// which is the paper's three instructions: MOV_SAT, SUB, MUL.
float microPatchOcclusion(MicroPatch micro, vec3 lsReceiver, vec2 lightHalf, float zLight) {
  if (lsReceiver.z <= micro.z || micro.z <= zLight) return 0.0;  // not between light and receiver
  float scale = (lsReceiver.z - zLight) / (lsReceiver.z - micro.z);
  vec2 a = lsReceiver.xy + (micro.lsMin - lsReceiver.xy) * scale;
  vec2 b = lsReceiver.xy + (micro.lsMax - lsReceiver.xy) * scale;
  vec4 ab = (vec4(a, b) + lightHalf.xyxy) / (2.0 * lightHalf.xyxy);  // light -> [0,1]^2
  vec4 s = clamp(ab, 0.0, 1.0);                                      // MOV_SAT
  vec2 overlap = s.zw - s.xy;                                        // SUB
  return overlap.x * overlap.y;                                      // MUL
}
