// Units, images and locations of the light_layers stage's passes (C++:
// stages/shared_inputs/light_layers.cpp): light_layers.frag's colour outputs in the far pass,
// and light_layers_risers.frag.
#define LIGHT_LAYERS_FAR_LOCATION 0       // the far layer (MAX blending)
#define LIGHT_LAYERS_FAR_COPY_LOCATION 1  // the same, kept as rasterized for the risers pass
#define RISERS_NEAR_UNIT 0
#define RISERS_FAR_IMAGE 0                // the far layer as rasterized (read)
#define RISERS_CLOSE_LOCATION 0
