// Difference view (app/window/views/ui_view_difference.h): result = A - B per channel, for comparisons in
// a texture view: light_layers.far - light_layers.near is the occluders' thickness (thesis
// §3.3, Fig 3.4), filter - trace what the filter changed, trace - reference the error.
// Variants by #define: A_ARRAY / B_ARRAY (2D array sources: the layer in uLayers), A_UINT /
// B_UINT (integer formats), RESULT_FORMAT (the image format: r32f, rg32f or rgba32f).
layout(local_size_x = 8, local_size_y = 8) in;
#if defined(A_UINT) && defined(A_ARRAY)
layout(binding = 0) uniform usampler2DArray sourceA;
#elif defined(A_UINT)
layout(binding = 0) uniform usampler2D sourceA;
#elif defined(A_ARRAY)
layout(binding = 0) uniform sampler2DArray sourceA;
#else
layout(binding = 0) uniform sampler2D sourceA;
#endif
#if defined(B_UINT) && defined(B_ARRAY)
layout(binding = 1) uniform usampler2DArray sourceB;
#elif defined(B_UINT)
layout(binding = 1) uniform usampler2D sourceB;
#elif defined(B_ARRAY)
layout(binding = 1) uniform sampler2DArray sourceB;
#else
layout(binding = 1) uniform sampler2D sourceB;
#endif
layout(binding = 0, RESULT_FORMAT) uniform writeonly image2D result;
layout(location = 0) uniform ivec2 uLayers;        // layer of A, of B (array sources)
layout(location = 1) uniform int uClipNegative;    // 1: negative differences become 0
layout(location = 2) uniform int uChannelsB;       // B's channel count: B's last channel
                                                   // serves A's further channels

vec4 fetchA(ivec2 p) {
#ifdef A_ARRAY
  return vec4(texelFetch(sourceA, ivec3(p, uLayers.x), 0));
#else
  return vec4(texelFetch(sourceA, p, 0));
#endif
}

vec4 fetchB(ivec2 p) {
#ifdef B_ARRAY
  return vec4(texelFetch(sourceB, ivec3(p, uLayers.y), 0));
#else
  return vec4(texelFetch(sourceB, p, 0));
#endif
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(result)))) return;
  vec4 a = fetchA(p), b = fetchB(p);
  vec4 d;
  for (int c = 0; c < 4; ++c) {
    d[c] = a[c] - b[min(c, uChannelsB - 1)];
    // Written as a test, not max(), so a NaN stays NaN (the view's overlay shows it).
    if (uClipNegative != 0 && d[c] < 0.0) d[c] = 0.0;
  }
  imageStore(result, p, d);
}
