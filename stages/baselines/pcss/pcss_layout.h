// PCSS (stages/baselines/pcss/pcss.cpp), read by C++ (stages/baselines/pcss/gpu_layout_pcss.h) and GLSL.
#define PCSS_PARAMS_BINDING 4  // uniform: PcssParams
#define PCSS_TAPS_BINDING 7    // storage: vec2 taps[]: blocker-search taps, then filter taps
// storage DEPTH_BOUNDS_BINDING (shared/ssm_layout.h): the near layer's DepthBounds, whose
// nearest occluder cuts the search cone (step 1): read on the GPU, never by the CPU
// The G-buffer and the near layer are read with texelFetch; the outputs written as images.
#define PCSS_NEAR_UNIT 2
#define PCSS_WS_POSITION_UNIT 0
#define PCSS_WS_NORMAL_UNIT 1
#define PCSS_VISIBILITY_IMAGE 0
#define PCSS_SEARCH_RADIUS_IMAGE 1
#define PCSS_BLOCKER_DEPTH_IMAGE 2
#define PCSS_FILTER_RADIUS_IMAGE 3

struct PcssParams {
  ivec4 taps;    // x = blocker-search taps, y = filter taps, z = per-pixel shift (0/1), w unused
};
