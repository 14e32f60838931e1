// The third depth layer (thesis §3.4): the eye's own depth, from the G-buffer. A point the
// near/far volume claims as solid is free space if the eye sees it: it lies in front of
// the visible surface at its pixel by more than the tolerance. A point on the visible
// surface itself (a sheet, the face the eye sees) stays solid. Outside the eye's view
// nothing is known, and the point stays solid, as with two layers.
layout(binding = TRACE_WS_POSITION_UNIT) uniform sampler2D wsPositionTexture;

bool hiddenFromEye(vec3 wsPoint) {
  vec4 clip = frame.clipFromWorld * vec4(wsPoint, 1.0);
  if (clip.w <= 0.0) return true;
  vec2 ndc = clip.xy / clip.w;
  if (any(greaterThan(abs(ndc), vec2(1.0)))) return true;
  ivec2 pixel = clamp(ivec2((ndc * 0.5 + 0.5) * vec2(frame.sizes.xy)), ivec2(0),
                      ivec2(frame.sizes.xy) - 1);
  gFetches += 1u;
  vec4 surface = texelFetch(wsPositionTexture, pixel, 0);
  if (surface.w == 0.0) return false;  // the eye sees the background through this point
  vec3 eye = frame.wsEyePosition.xyz;
  return distance(wsPoint, eye) > distance(surface.xyz, eye) - trace.eye.x;
}
