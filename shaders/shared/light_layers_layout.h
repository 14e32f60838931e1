// Units and locations of light_layers_risers.comp (C++: stages/shared_inputs/light_layers.cpp).
#define RISERS_NEAR_UNIT 0
#define RISERS_FAR_UNIT 1
#define RISERS_FAR_IMAGE 0
#define RISERS_CLOSE_LOCATION 0
#define RISERS_BLOCK 2  // texels per axis of one invocation's block (4: slower, bench/llvmpipe-writes)
