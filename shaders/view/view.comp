// Texture view: maps a stage output to display colours exactly as the CPU twin does for
// "PNG as displayed" (app/window/views/ui_view_settings.cpp displayRgb8ForView over app/io/colormap.cpp):
// channel toggles, black point and scale, colormap, NaN/Inf/negative overlay. Every step
// that rounds is written so it rounds the same way in C++ (`precise` forbids fused
// multiply-adds; bytes are rounded here, not by the image store).
// Variants by #define: SOURCE_ARRAY (2D array textures: the N-buffer levels, uLayer picks
// one), SOURCE_UINT (integer formats such as R32UI masks). Depth textures read as sampler2D.
layout(local_size_x = 8, local_size_y = 8) in;
#if defined(SOURCE_UINT) && defined(SOURCE_ARRAY)
layout(binding = 0) uniform usampler2DArray source;
#elif defined(SOURCE_UINT)
layout(binding = 0) uniform usampler2D source;
#elif defined(SOURCE_ARRAY)
layout(binding = 0) uniform sampler2DArray source;
#else
layout(binding = 0) uniform sampler2D source;
#endif
layout(binding = 0, rgba8) uniform writeonly image2D displayImage;
layout(location = 0) uniform int uSingle;        // -1: RGB (gray per channel); else this channel
layout(location = 1) uniform vec2 uBlackScale;   // black point, 1 / (white - black) (0 if equal)
layout(location = 2) uniform int uColormap;      // 0 gray, 1 perceptual, 2 diverging, 3 categorical
layout(location = 3) uniform int uChannelCount;
layout(location = 4) uniform int uChannelMask;   // bit c: channel c enabled
layout(location = 5) uniform int uOverlay;       // 1: paint NaN / Inf / negative
layout(location = 6) uniform int uLayer;         // SOURCE_ARRAY only

vec4 fetchTexel(ivec2 pixel) {
#ifdef SOURCE_ARRAY
  return vec4(texelFetch(source, ivec3(pixel, uLayer), 0));
#else
  return vec4(texelFetch(source, pixel, 0));
#endif
}

// Same rounding as C++ lround(clamp(v, 0, 1) * 255) for v >= 0.
float toByte(float v) {
  precise float scaled = clamp(v, 0.0, 1.0) * 255.0;
  return floor(scaled + 0.5);
}

vec3 viridis(float t) {
  const vec3 c0 = vec3(0.2777273272234177, 0.005407344544966578, 0.3340998053353061);
  const vec3 c1 = vec3(0.1050930431085774, 1.404613529898575, 1.384590162594685);
  const vec3 c2 = vec3(-0.3308618287255563, 0.214847559468213, 0.09509516302823659);
  const vec3 c3 = vec3(-4.634230498983486, -5.799100973351585, -19.33244095627987);
  const vec3 c4 = vec3(6.228269936347081, 14.17993336680509, 56.69055260068105);
  const vec3 c5 = vec3(4.776384997670288, -13.74514537774601, -65.35303263337234);
  const vec3 c6 = vec3(-5.435455855934631, 4.645852612178535, 26.3124352495832);
  precise vec3 rgb = c0 + t * (c1 + t * (c2 + t * (c3 + t * (c4 + t * (c5 + t * c6)))));
  return rgb;
}

// One raw value -> three bytes (0..255), as app/io/colormap.cpp applyColormap + displayRgb8.
vec3 mapValue(float raw) {
  if (isnan(raw)) return vec3(255, 0, 255);
  if (isinf(raw)) return raw > 0.0 ? vec3(255) : vec3(0);
  precise float t = clamp((raw - uBlackScale.x) * uBlackScale.y, 0.0, 1.0);
  if (uColormap == 1) {
    vec3 rgb = viridis(t);
    return vec3(toByte(rgb.r), toByte(rgb.g), toByte(rgb.b));
  }
  if (uColormap == 2) {  // blue (0) - white (0.5) - red (1)
    precise float s = 2.0 * t - 1.0;
    precise float down = 1.0 + s, up = 1.0 - s;
    return s < 0.0 ? vec3(toByte(down), toByte(down), 255) : vec3(255, toByte(up), toByte(up));
  }
  if (uColormap == 3) {
    const vec3 palette[8] = vec3[8](vec3(40, 40, 40), vec3(250, 220, 90), vec3(40, 70, 200),
                                    vec3(60, 200, 90), vec3(220, 60, 60), vec3(160, 90, 220),
                                    vec3(90, 210, 220), vec3(240, 150, 60));
    return palette[int(floor(abs(raw) + 0.5)) % 8];  // lround(|raw|) % 8
  }
  return vec3(toByte(t));
}

bool enabled(int channel) { return (uChannelMask & (1 << channel)) != 0; }

void main() {
  ivec2 size = imageSize(displayImage);
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (pixel.x >= size.x || pixel.y >= size.y) return;
  vec4 texel = fetchTexel(pixel);
  vec3 bytes;
  // 1. Map: one channel through the colormap, or each colour channel through gray.
  if (uSingle >= 0) {
    bytes = mapValue(texel[uSingle]);
  } else {
    int shown = min(uChannelCount, 3);
    for (int c = 0; c < 3; ++c) {
      int from = min(c, shown - 1);
      bytes[c] = enabled(from) ? mapValue(texel[from]).r : 0.0;
    }
  }
  // 2. Overlay over the shown channels: NaN, then Inf, then negative.
  if (uOverlay != 0) {
    bool nan = false, inf = false, negative = false;
    for (int c = 0; c < 4; ++c) {
      bool shown = uSingle >= 0 ? c == uSingle : (c < min(uChannelCount, 3) && enabled(c));
      if (!shown) continue;
      nan = nan || isnan(texel[c]);
      inf = inf || isinf(texel[c]);
      negative = negative || texel[c] < 0.0;
    }
    if (nan) bytes = vec3(255, 0, 255);
    else if (inf) bytes = vec3(0, 255, 0);
    else if (negative) bytes = vec3(0, 0, 255);
  }
  imageStore(displayImage, pixel, vec4(bytes / 255.0, 1.0));
}
