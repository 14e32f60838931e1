// Units and locations of the light_layers stage's passes (C++:
// stages/shared_inputs/light_layers/light_layers.cpp): light_layers.frag's colour outputs in the far pass,
// and light_layers_risers.frag.
#define LIGHT_LAYERS_FAR_LOCATION 0    // the far layer (where the depth test passes)
#define LIGHT_LAYERS_SLOPE_LOCATION 1  // the far surface's plane: d(1/z)/dx, d(1/z)/dy per texel
#define RISERS_NEAR_UNIT 0
#define RISERS_FAR_UNIT 1            // the far layer as rasterized (the far pass's depth buffer)
#define RISERS_SLOPE_UNIT 2          // the far surface's slope (LIGHT_LAYERS_SLOPE_LOCATION)
