// PCSS (stages/baselines/pcss.cpp), read by C++ (app/gl/gpu_layout_pcss.h) and GLSL.
#define PCSS_PARAMS_BINDING 4  // uniform: PcssParams
#define PCSS_TAPS_BINDING 7    // storage: vec2 taps[]: blocker-search taps, then filter taps

struct PcssParams {
  ivec4 taps;    // x = blocker-search taps, y = filter taps, z = per-pixel shift (0/1), w unused
  vec4 search;   // x = z of the nearest occluder in the map (the search plane), yzw unused
};
