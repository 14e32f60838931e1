// Layouts of stage `raster4d` (Wang et al. 2020, 4D rasterization; stages/raster4d/), read
// by C++ (stages/raster4d/raster4d/raster4d_gpu.h checks them with static_assert) and GLSL
// (shaders/raster4d/raster4d/raster4d.glsl). std140 uniform block / std430 storage, 16-byte members.
//
// Spaces. *Light space* (ls): origin at the light's centre, x along the light's right, y
// along its up, z = d the distance in front of the light plane (along forward). The light
// samples are the centres of the m x m cells: L_ij = (-a + j du, -b + i dv, 0), row i
// along up, column j along right; bit j of row i is sample k = i m + j, as the reference's
// uniform sampling numbers them. *P space*: the plane P (depth D, parallel to the light)
// in light-space xy. Proj4(X) (§3.1) is the rectangle where rays from X through the four
// outer samples hit P: centre X.xy D/d, half size (a, b) |D/d - 1|.
#define RASTER4D_PARAMS_BINDING 5  // uniform Raster4dParams
// Storage buffers, per pass (within GL 4.5's minimum of 8 per compute shader). The data:
//  receivers    vec4 per eye pixel: ls (x, y, d); w = 0 background, 1 receiver, 2 at or
//               behind the light plane
//  triangles    vec4 x 3 per occluder triangle, world space; lsTriangles: light space
//  boxes        vec4 per triangle: P-space AABB of its Proj4 (min xy, max xy)
//  counts       uint per FB pixel (samples or triangles assigned); starts: their exclusive
//               prefix sum (FB pixels + 1); cursors: scatter cursors
//  sampleList   uvec2 per sample entry (eye pixel, FB pixel); triangleList: uint per entry
//  masks        uint per (eye pixel, light row, word); cellPairs: uvec4 per FB pixel
//               (pairs considered, kept, occluding, 0)
//  plan         Raster4dPlan, then Raster4dBandPlan per band slot (raster4d_plan.comp);
//               step5Commands: uvec4 per band slot and STEP 5 dispatch (budget.w per slot)
// Nothing the GPU counts is read back inside the stage's run: what a later pass's size or
// placement depends on is written by a pass into these buffers and reaches the later passes
// as indirect dispatch commands or as parts of Raster4dParams copied on the GPU
// (glCopyNamedBufferSubData: the state's plane and fb, a band slot's band and dispatch).
// STEP 2 (raster4d_receivers.comp, then raster4d_place.comp)
#define R4D_RECEIVERS_RECEIVERS 0
#define R4D_RECEIVERS_STATE 1
#define R4D_PLACE_STATE 0
// STEP 3 (raster4d_samples.comp)
#define R4D_SAMPLES_RECEIVERS 0
#define R4D_SAMPLES_COUNTS 1
#define R4D_SAMPLES_STARTS 2
#define R4D_SAMPLES_CURSORS 3
#define R4D_SAMPLES_LIST 4
// STEP 4 (raster4d_triangles.comp)
#define R4D_TRIANGLES_TRIANGLES 0
#define R4D_TRIANGLES_LS_TRIANGLES 1
#define R4D_TRIANGLES_BOXES 2
#define R4D_TRIANGLES_STATE 3
#define R4D_TRIANGLES_COUNTS 4
#define R4D_TRIANGLES_STARTS 5
#define R4D_TRIANGLES_CURSORS 6
#define R4D_TRIANGLES_LIST 7
// prefix sums (raster4d_scan.comp)
#define R4D_SCAN_COUNTS 0
#define R4D_SCAN_STARTS 1
// STEP 5 (raster4d_occlusion.comp)
#define R4D_OCCLUSION_RECEIVERS 0
#define R4D_OCCLUSION_LS_TRIANGLES 1
#define R4D_OCCLUSION_BOXES 2
#define R4D_OCCLUSION_SAMPLE_LIST 3
#define R4D_OCCLUSION_TRIANGLE_STARTS 4
#define R4D_OCCLUSION_TRIANGLE_LIST 5
#define R4D_OCCLUSION_MASKS 6
#define R4D_OCCLUSION_CELL_PAIRS 7
// the bands, STEP 5's chunks and the budget (raster4d_plan.comp)
#define R4D_PLAN_SAMPLE_COUNTS 0
#define R4D_PLAN_TRIANGLE_COUNTS 1
#define R4D_PLAN_SAMPLE_STARTS 2
#define R4D_PLAN_TRIANGLE_STARTS 3
#define R4D_PLAN_STATE 4
#define R4D_PLAN_PLAN 5
#define R4D_PLAN_STEP5_COMMANDS 6
// visibility (raster4d_resolve.comp)
#define R4D_RESOLVE_RECEIVERS 0
#define R4D_RESOLVE_MASKS 1
// views (raster4d_cells.comp)
#define R4D_CELLS_TRIANGLE_COUNTS 0
#define R4D_CELLS_SAMPLE_COUNTS 1
#define R4D_CELLS_PAIRS 2

#define RASTER4D_SCAN_GROUP 256
#define RASTER4D_PLAN_GROUP 256
#define RASTER4D_MAX_GROUPS 65535  // groups per dimension of a dispatch (GL 4.5's minimum)
#define R4D_OCCLUSION_CHUNK_BASE_LOCATION 0  // uniform int: the first chunk of a STEP 5 dispatch
#define RASTER4D_ASSIGN_L0 1     // modes.x: Algorithm 2 (one FB pixel per sample)
#define RASTER4D_ASSIGN_PROJ4 0  // modes.x: Algorithm 1 lines 8-11 (every pixel of Proj4)

struct Raster4dParams {
  mat4 lsFromWorld;  // world -> light space (rows: right, up, forward; origin the centre)
  vec4 light;        // x = a, y = b (offset of the outer samples), z = du, w = dv
  vec4 plane;        // x = D (depth of P), y = tolerance in P space (conservative), z = smallest
                     // origin offset along the normal (world; reference_origin.h), w = smallest
                     // receiver/occluder depth
  vec4 fb;           // xy = P-space minimum of FB, zw = FB pixels per P-space unit
  ivec4 sizes;       // x, y = FB pixels; z, w = eye image
  ivec4 band;        // x = first FB row, y = end row (exclusive); z = sample entry base,
                     // w = triangle entry base (the band's first entries). The count
                     // passes run over the same row windows (x, y), with z = w = 0.
  ivec4 modes;       // x = sample assignment (RASTER4D_ASSIGN_*), y = early rejection,
                     // z = row masks (0: per-sample tests), w = occluder triangles
  ivec4 pick;        // xy = picked eye pixel (GL order; -1 none), z = m, w = words per row
  ivec4 dispatch;    // x = sample entries of the band (STEP 5: one invocation per entry and
                     // chunk, the chunk in the z dimension), y = elements to scan, z = chunks,
                     // w = list entries per FB pixel in one chunk (the plan reads it)
  ivec4 options;     // x = row culling (not in the paper: only the light rows the triangle's
                     // cone from the sample can reach); the plan's inputs: y = raster4d.max_entries,
                     // z = FB rows per band at most (the loop budget), w = band slots
  uvec4 budget;      // xy = most pairs STEP 5 may test (a double's low and high words),
                     // z = 1 when raster4d.budget limits them, w = STEP 5 commands per band slot
};

// Step 2's bounds (floats as order-preserving uints, for atomicMin/Max) and totals, and the
// placement of P and the FB computed from them on the GPU (raster4d_place.comp).
struct Raster4dState {
  uvec4 boundsMin;  // x = min (x - a)/d, y = min (y - b)/d over receivers
  uvec4 boundsMax;  // x = max (x + a)/d, y = max (y + b)/d, z = max d over receivers
  uvec4 counts;     // x = receivers (d > 0), y = behind the light plane, z = occluders binned,
                    // w = occluders crossing the light plane (binned to the whole FB)
  vec4 plane;       // xy: Raster4dParams.plane.xy (D, tolerance); 0 without receivers
  vec4 fb;          // Raster4dParams.fb; 0 without receivers
};

// The plan after STEP 3-4's counts (raster4d_plan.comp), read by the stage after the frame.
struct Raster4dPlan {
  uvec4 totals;  // x = bands, y = STEP 5 chunks, z = sample entries, w = triangle entries
  uvec4 pairs;   // xy = (sample, triangle) pairs STEP 5 tests (a double's words), z = 1 if
                 // STEP 5 runs (within raster4d.budget), w = the longest triangle list
};

// One band slot of FB rows: the band's part of Raster4dParams (copied into it on the GPU)
// and the indirect commands (x, y, z groups) of its passes, all zero for a slot past the
// last band or when the budget refuses STEP 5.
struct Raster4dBandPlan {
  ivec4 band;              // Raster4dParams.band: first row, end row, sample and triangle base
  ivec4 dispatch;          // Raster4dParams.dispatch: sample entries, 0, chunks, chunk size
  uvec4 samplesCommand;    // STEP 3's scatter: the eye image in 8 x 8 groups
  uvec4 trianglesCommand;  // STEP 4's scatter: the occluder triangles, 64 per group
};
// STEP 5's commands of a slot (step5Commands, budget.w per slot): command k runs the chunks
// from k RASTER4D_MAX_GROUPS on, one per group in z (a dimension holds at most that many).
