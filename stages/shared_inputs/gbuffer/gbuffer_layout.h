// Locations of gbuffer.frag (C++: stages/shared_inputs/gbuffer/gbuffer.cpp, which passes the base
// colour location to GpuScene::draw) and its colour attachments.
#define GBUFFER_BASE_COLOR_LOCATION 1
#define GBUFFER_ALBEDO_ATTACHMENT 0
#define GBUFFER_NORMAL_ATTACHMENT 1
#define GBUFFER_POSITION_ATTACHMENT 2
