// The light, as the `light` stage hands it to every stage that reads the light's maps
// (stages/shared_inputs/light/light.cpp): read by C++ (app/gl/gpu_layout.h) and GLSL
// (#include "shared/frame.glsl"). std140, 16-byte members only; bound at uniform binding
// LIGHT_BLOCK_BINDING while a stage that declared the `light` input runs.
//
// Light space (thesis §3, Eq 3.1). The light is a rectangle; its projection point sits
// lightDepth = max(width, height) / (2 tan(fov/2)) behind the center, so the light
// rectangle is exactly the frustum's cross-section at the near plane z = lightDepth.
// Depth encoding (every stage): the layers store the normalized *linear* light depth
//     lsDepth = (z - zNear) / (zFar - zNear),  z = distance along the light axis from the
// projection point, zNear = lightDepth (the light plane), zFar = beyond the scene bounds.
// Linear depth keeps float precision uniform over the range (a tiny light makes zNear tiny,
// which ruins perspective NDC depth) and makes Eq 3.2 and Eq 3.3 direct; 1/z is what is
// linear along a projected ray, and stages convert with lsDepthToZ / zToLsDepth.
// Cleared values follow thesis §3.3: near layer 1 (nothing in front), far layer 0.
#define LIGHT_BLOCK_BINDING 2

struct LightUniforms {
  mat4 lightClipFromWorld;  // perspective from the projection point; xy in [-1,1] is the map
  mat4 lightViewFromWorld;  // right-handed, looking down -z
  vec4 wsLightCenter;       // xyz, w = light area (width * height)
  vec4 wsLightRight;        // xyz unit, w = width / 2
  vec4 wsLightUp;           // xyz unit, w = height / 2
  vec4 wsLightForward;      // xyz unit (direction the light faces), w = lightDepth (Eq 3.1)
  vec4 lightDepthRange;     // x = zNear (= lightDepth), y = zFar, z = tan(fovX/2), w = tan(fovY/2)
  uvec4 mapSize;            // xy = light maps (texels), z = depth layers (1-3, §3.2-3.4),
                            // w unused
  vec4 bias;                // Eq 3.2 group: x = constant (world), y = adaptive (0/1),
                            // z = min cosine, w = normal offset (texels; bias.glsl)
  uvec4 sampling;           // x = light-sample hash (HASH_*), yzw unused
};
