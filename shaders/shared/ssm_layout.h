// Soft shadow maps (stages/soft_shadow_maps/ssm/ssm.cpp), read by C++ (app/gl/gpu_layout_ssm.h)
// and GLSL. std140/std430 with 16-byte members only.
#define SSM_PARAMS_BINDING 4    // uniform: SsmParams
#define DEPTH_BOUNDS_BINDING 5  // storage: DepthBounds (shaders/shared/depth_bounds.comp)
#define SSM_COUNTERS_BINDING 6  // storage: SsmCounters
#define SSM_WORK_BINDING 7      // storage: SsmWork (ssm_patches.vert)

// depth_bounds.comp
#define DEPTH_BOUNDS_MAP_UNIT 0
#define DEPTH_BOUNDS_EMPTY_LOCATION 0  // the cleared value: no surface
// ssm_patches.vert/.frag
#define SSM_PATCHES_OCCLUDER_UNIT 0
#define SSM_PATCHES_RECEIVER_UNIT 1
// ssm_picked_light.vert
#define SSM_PICKED_OCCLUDER_UNIT 0
#define SSM_PICKED_RECEIVER_UNIT 1
#define SSM_PICKED_WS_POSITION_UNIT 2
// ssm_project.comp (a screen pass: uniforms after ROW_OFFSET_LOCATION; it has none)
#define SSM_PROJECT_WS_POSITION_UNIT 0
#define SSM_PROJECT_RECEIVER_UNIT 1
#define SSM_PROJECT_SOFT_SHADOW_MAP_UNIT 2
#define SSM_PROJECT_VISIBILITY_IMAGE 0

struct SsmParams {
  ivec4 map;        // x = resolution n of the occluder, receiver and soft shadow maps,
                    // y = pass (0: front/nearest occluders, 1: back/farthest), z = passes (1, 2),
                    // w = 1 while drawing the picked occluder texel's footprint only
  ivec4 pick;       // xy = picked receiver's eye pixel (GL rows; -1: none),
                    // zw = picked occluder texel (-1: none)
  vec4 tolerance;   // x = receiver tolerance (in depth steps between neighbouring texels),
                    // y = 1: this draw adds its quads' fragments to SsmWork (one draw per
                    // pass: the first scissor tile), zw unused
};

// Min and max of a depth map's texels that hold a surface, as float bits (non-negative
// floats order like their bits), and how many texels hold one.
struct DepthBounds {
  uint minBits, maxBits, count, unused;
};

struct SsmCounters {
  uint clampedPixels;   // eye pixels whose accumulated occlusion exceeded 1 (clamped)
  uint occluderPixels;  // eye pixels in front of the receiver map: occluders, not shadowed
  uint unused0, unused1;
};

// The micro-patch quads' fragments (texel centres inside each quad, summed over the
// instances of a pass's first draw), a 64-bit count as two words: the measured work that
// the cost estimate (stages/soft_shadow_maps/ssm/ssm_cost.h) predicts.
struct SsmWork {
  uint low, high, unused0, unused1;
};
