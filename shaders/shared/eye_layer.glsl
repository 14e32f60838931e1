// The third depth layer (thesis §3.4): the eye's own depth, from the G-buffer. A point the
// near/far volume claims as solid is free space if the eye sees it: it lies in front of
// the visible surface at its pixel by more than the tolerance. A point on the visible
// surface itself (a sheet, the face the eye sees) stays solid. Outside the eye's view
// nothing is known, and the point stays solid, as with two layers.
//
// Silhouettes: a point on an occluder within a pixel of its outline in the eye's
// image may fall in a pixel that shows what lies behind the occluder (the ground, or the
// background); one fetch then called the occluder's own point "seen in front of the
// surface", i.e. free, and light leaked around every silhouette (a 0.05-wide light over a
// plate, 2x2 rays: mean |error| in shadow 0.0087 with two layers, 0.029 with three, maximum
// 0.28 and 0.60). The point is now free only if it lies in front of the visible surface at
// every covered pixel of the 3x3 block around its projection: within a pixel of an outline
// the occluder's own pixels keep it solid.
//
// Oblique surfaces: seen at a grazing angle a surface's distance from the eye
// changes across one pixel by more than the tolerance (the built-in plate's top at 128x96:
// about 0.03 against 0.02), so a point on the visible surface but in the near half of its
// pixel lay "in front" of the pixel centre's sample; inside the surface a nearer neighbour
// kept it solid, but along the outline nearest the eye no neighbour shows the surface, and
// light leaked under the plate's front edge (three layers: mean |error| in shadow 0.0893
// against 0.0799 with two layers, 146 pixels at 128x96). The surface's distance is now the
// nearer of the pixel centre's and of its tangent plane (G-buffer position and normal) met
// along the eye ray through the point: a point on the plane is never in front of it, and
// taking the nearer never frees a point the centre's distance kept solid (a neighbour's
// plane extended across a crease could lie far behind; with it alone engine's three layers
// got 0.0015 worse). Where the plane nearly contains the eye ray its distance along the ray
// is meaningless: the centre's distance alone.
layout(binding = TRACE_WS_POSITION_UNIT) uniform sampler2D wsPositionTexture;
layout(binding = TRACE_WS_NORMAL_UNIT) uniform sampler2D wsNormalTexture;

// Distance from the eye, along the eye ray `rayDirection`, to the tangent plane of a pixel's
// visible surface; "infinitely far" where the plane nearly contains the ray.
float planeDistanceAlong(vec3 eye, vec3 rayDirection, ivec2 at, vec3 surfacePoint) {
  vec3 normal = texelFetch(wsNormalTexture, at, 0).xyz;
  float facing = dot(normal, rayDirection);
  return abs(facing) < 0.1 ? 3.0e38 : dot(normal, surfacePoint - eye) / facing;
}

bool hiddenFromEye(vec3 wsPoint) {
  vec4 clip = frame.clipFromWorld * vec4(wsPoint, 1.0);
  if (clip.w <= 0.0) return true;
  vec2 ndc = clip.xy / clip.w;
  if (any(greaterThan(abs(ndc), vec2(1.0)))) return true;
  ivec2 size = ivec2(frame.sizes.xy);
  ivec2 pixel = clamp(ivec2((ndc * 0.5 + 0.5) * vec2(size)), ivec2(0), size - 1);
  vec3 eye = frame.wsEyePosition.xyz;
  float pointDistance = distance(wsPoint, eye);
  vec3 rayDirection = (wsPoint - eye) / max(pointDistance, 1e-20);
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      ivec2 at = clamp(pixel + ivec2(dx, dy), ivec2(0), size - 1);
      gFetches += 1u;
      vec4 surface = texelFetch(wsPositionTexture, at, 0);
      if (surface.w == 0.0) continue;  // background: the eye sees through this pixel
      // Behind the sample: solid without reading the normal; else the plane decides.
      if (pointDistance > distance(surface.xyz, eye) - trace.eye.x) return true;
      gFetches += 1u;
      if (pointDistance > planeDistanceAlong(eye, rayDirection, at, surface.xyz) - trace.eye.x)
        return true;
    }
  return false;
}
