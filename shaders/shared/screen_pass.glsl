// Common head of the screen-space compute passes: 8x8 groups, dispatched in row bands
// (app/gl/shader_program.h dispatchRows) with the band's first row in uRowOffset.
#include "frame.glsl"
#include "screen_pass_layout.h"
layout(local_size_x = 8, local_size_y = 8) in;
layout(location = ROW_OFFSET_LOCATION) uniform int uRowOffset;

// The eye pixel of this invocation, or ivec2(-1) outside the image.
ivec2 screenPixel() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy) + ivec2(0, uRowOffset);
  if (pixel.x >= int(frame.sizes.x) || pixel.y >= int(frame.sizes.y)) return ivec2(-1);
  return pixel;
}
