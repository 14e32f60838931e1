// Layouts of the trace stage, read by C++ (app/gl/gpu_layout_trace.h) and GLSL.
// std140 uniform block TraceBlock at binding 1; std430 storage buffers: per-pixel step
// records at binding 0, totals at binding 1. Only 16-byte members (see frame_block.h).

// Bindings of trace.comp and trace_forward.frag (and the test shader tests/ray_query.comp):
#define TRACE_PARAMS_BINDING 1    // uniform: TraceParams
#define TRACE_RECORDS_BINDING 0   // storage: uvec4 header (x = count), TraceStep[]
#define TRACE_TOTALS_BINDING 1    // storage: uint[TOTAL_COUNT]
// trace.comp writes each pixel's counts as one record of two uvec4 (per-pixel records,
// reduced by trace_totals.comp, rather than an atomicAdd per total and pixel).
// Record: [0].x = rays | searched << 10 | early backface << 20, [0].y = early inside |
// early region << 10 (each at most the pixel's rays, TRACE_COUNT_BITS wide), [0].z = fetches,
// [0].w = iterations, [1].x = the early-out tests' fetches, [1].yzw = 0. Record index: the
// pixel's place in classify's list, or y * width + x where every pixel is traced.
// (trace_forward.frag adds to the totals directly.)
#define TRACE_PARTIALS_BINDING 2  // storage: TRACE_RECORD_UVEC4S uvec4 per pixel
#define TRACE_RECORD_UVEC4S 2
#define TRACE_COUNT_BITS 10       // > 2 log2(the most rays per side)
#define TRACE_TOTALS_RECORDS_LOCATION 0      // trace_totals.comp: records to add up at most
#define TRACE_TOTALS_FROM_LIST_LOCATION 1    // 1: as many as classify listed
#define TRACE_TOTALS_RECORDS_PER_INVOCATION 64
// (storage CLASSIFY_LIST_BINDING: the pixel list of classify_layout.h)
// Texture units (read with texelFetch) and image units (written) of the trace:
#define TRACE_WS_POSITION_UNIT 0  // eye_layer.glsl, trace.comp
#define TRACE_WS_NORMAL_UNIT 1
#define TRACE_NEAR_UNIT 2         // trace_ray.glsl: the layers and the hierarchy
#define TRACE_FAR_UNIT 3
#define TRACE_LEVELS_UNIT 4       // the N-buffer (2D array texture)
#define TRACE_MINMAX_UNIT 5       // the min-max mipmap's levels >= 1 (minmax.glsl)
#define TRACE_MASK_UNIT 6         // trace.comp: classify's class and bounds
#define TRACE_ZRANGE_UNIT 7
#define TRACE_VISIBILITY_IMAGE 0  // trace.comp (written)
#define TRACE_COST_IMAGE 1
#define TRACE_PIXELS_LOCATION 1   // which pixels (TRACE_PIXELS_*); ROW_OFFSET_LOCATION = 0
                                  // holds the first row, or the band's first group
#define TRACE_PIXELS_ALL 0        // every pixel, rows from the row offset
#define TRACE_PIXELS_LISTED 1     // the pixels classify listed, groups from the row offset
#define TRACE_PIXELS_RECORDED 2   // the recorded pixel alone

#define SEARCH_LINEAR 0
#define SEARCH_LINEAR_BINARY 1
#define SEARCH_HIERARCHICAL 2

// The hierarchy the searches and the region early out read (trace.limits.z).
#define HIERARCHY_NBUFFER 0       // thesis §3.5: windows of 2^n around each texel
#define HIERARCHY_MINMAX 1        // quadtree-aligned cells (min-max mipmap)

#define SAMPLING_JITTERED 0
#define SAMPLING_RANDOM 1

// Decisions in a step record (the visualizer draws them; tests add them up).
#define STEP_DESCEND 0      // hierarchical: the window may hold an occluder: go finer
#define STEP_ADVANCE 1      // hierarchical: nothing in the window: step past it
#define STEP_ASCEND 2       // (recorded with ADVANCE: the next window is coarser)
#define STEP_HIT 3          // the ray is blocked (terminal)
#define STEP_MISS 4         // the ray reached its end (terminal)
#define STEP_EARLY_BACKFACE 5  // terminal: the light sample is behind the surface (§3.7)
#define STEP_EARLY_INSIDE 6    // terminal: the end point is inside a solid (§3.7)
#define STEP_EARLY_REGION 7    // terminal: the ray's region holds no occluder (§3.7)
#define STEP_SAMPLE 8          // linear: one sample along the ray
#define STEP_REFINE 9          // binary refinement sample
#define STEP_EYE_VISIBLE 10    // three layers: inside the volume but seen by the eye: free
#define STEP_CLASSIFIED 11     // terminal for all rays: classify said lit or umbra (§3.6)

// Totals (binding 1), indices:
#define TOTAL_RAYS 0          // rays set up (n x n per traced pixel)
#define TOTAL_RAYS_SEARCHED 1 // rays that reached a search loop
#define TOTAL_FETCHES 2       // texel fetches in early outs and searches (all of them)
#define TOTAL_ITERATIONS 3    // search loop iterations
#define TOTAL_EARLY_BACKFACE 4
#define TOTAL_EARLY_INSIDE 5
#define TOTAL_EARLY_REGION 6
#define TOTAL_ITERATION_CAP 7      // rays stopped by the iteration cap (should stay 0)
#define TOTAL_EARLY_OUT_FETCHES 8  // the fetches of the early-out tests (inside, region; §3.7);
                                   // TOTAL_FETCHES minus these are the searches' fetches
#define TOTAL_COUNT 12

struct TraceParams {
  ivec4 config;    // x = rays per side n, y = sampling, z = search, w = layers (1, 2, 3)
  ivec4 switches;  // x = early out backface, y = early out inside, z = early out region,
                   // w = shorten rays (§3.7)
  ivec4 limits;    // x = iteration cap, y = binary refinement steps, z = hierarchy
                   // (HIERARCHY_*),
                   // w = use classification (skip lit / umbra pixels)
  vec4 stepping;   // x = linear step (texels), yzw unused (the bias group is light.bias)
  ivec4 record;    // xy = pixel whose steps are recorded (-1: none), z = record capacity,
                   // w = the hierarchy's top level
  vec4 eye;        // x = eye-visibility tolerance (world units, three layers), yzw unused
};

struct TraceStep {
  ivec4 header;   // x = ray index, y = level (-1: none), z = decision (STEP_*), w = iteration
  ivec4 window;   // texel rectangle x0, y0, x1, y1 (inclusive) of the visited window
  vec4 depths;    // x = zNearMin, y = zFarMax (window), z, w = ray lsDepth at entry / exit
  vec4 stepping;  // x = s before, y = s after, zw = texel-space point at s after
};
