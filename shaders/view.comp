// Texture view: maps a stage output to display colours exactly as app/colormap.cpp does
// for the PNG export (channel, black/white point, colormap; NaN magenta, +Inf white).
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D source;
layout(binding = 0, rgba8) uniform writeonly image2D displayImage;
layout(location = 0) uniform int uChannel;   // -1: RGB
layout(location = 1) uniform vec2 uRange;    // black, white
layout(location = 2) uniform int uColormap;  // 0 gray, 1 perceptual, 2 diverging, 3 categorical
layout(location = 3) uniform int uChannelCount;

vec3 viridis(float t) {
  const vec3 c0 = vec3(0.2777273272234177, 0.005407344544966578, 0.3340998053353061);
  const vec3 c1 = vec3(0.1050930431085774, 1.404613529898575, 1.384590162594685);
  const vec3 c2 = vec3(-0.3308618287255563, 0.214847559468213, 0.09509516302823659);
  const vec3 c3 = vec3(-4.634230498983486, -5.799100973351585, -19.33244095627987);
  const vec3 c4 = vec3(6.228269936347081, 14.17993336680509, 56.69055260068105);
  const vec3 c5 = vec3(4.776384997670288, -13.74514537774601, -65.35303263337234);
  const vec3 c6 = vec3(-5.435455855934631, 4.645852612178535, 26.3124352495832);
  return c0 + t * (c1 + t * (c2 + t * (c3 + t * (c4 + t * (c5 + t * c6)))));
}

vec3 mapValue(float raw) {
  if (isnan(raw)) return vec3(1, 0, 1);
  if (isinf(raw)) return raw > 0.0 ? vec3(1) : vec3(0);
  float range = uRange.y - uRange.x;
  float t = clamp(range != 0.0 ? (raw - uRange.x) / range : 0.0, 0.0, 1.0);
  if (uColormap == 1) return clamp(viridis(t), 0.0, 1.0);
  if (uColormap == 2) {
    float s = 2.0 * t - 1.0;
    return s < 0.0 ? vec3(1.0 + s, 1.0 + s, 1.0) : vec3(1.0, 1.0 - s, 1.0 - s);
  }
  if (uColormap == 3) {
    const vec3 palette[8] = vec3[8](vec3(40, 40, 40), vec3(250, 220, 90), vec3(40, 70, 200),
                                    vec3(60, 200, 90), vec3(220, 60, 60), vec3(160, 90, 220),
                                    vec3(90, 210, 220), vec3(240, 150, 60));
    return palette[int(round(abs(raw))) % 8] / 255.0;
  }
  return vec3(t);
}

void main() {
  ivec2 size = imageSize(displayImage);
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (pixel.x >= size.x || pixel.y >= size.y) return;
  vec4 texel = texelFetch(source, pixel, 0);
  vec3 color;
  if (uChannel < 0) {
    int shown = min(uChannelCount, 3);
    for (int c = 0; c < 3; ++c) color[c] = mapValue(texel[min(c, shown - 1)]).r;
  } else {
    color = mapValue(texel[uChannel]);
  }
  imageStore(displayImage, pixel, vec4(color, 1.0));
}
