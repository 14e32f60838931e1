// raster4d STEP 2, the placement (Fig 2): P at the farthest receiver's depth D, and the FB
// over the receivers' Proj4 bounds on P, [D (x - a)/d + a, D (x + a)/d - a] per axis, from
// the bounds raster4d_receivers.comp reduced. Written into the state; the stage copies them
// into Raster4dParams on the GPU, so no later pass waits for the CPU to read them. One value
// for the whole image: the first invocation computes it. `precise`: each operation rounded
// as written (no fused multiply-add), so the placement is the one the CPU computed before.
#include "raster4d.glsl"
layout(local_size_x = 64) in;
layout(std430, binding = R4D_PLACE_STATE) buffer State { Raster4dState state; };

void main() {
  if (gl_LocalInvocationIndex != 0u) return;
  state.plane = vec4(0.0);  // no receiver: no plane, nothing is binned (raster4d_triangles.comp)
  state.fb = vec4(0.0);
  if (state.counts.x == 0u) return;
  float depth = floatFromOrdered(state.boundsMax.z);
  precise vec2 lo = depth * vec2(floatFromOrdered(state.boundsMin.x), floatFromOrdered(state.boundsMin.y)) +
                    r4d.light.xy;
  precise vec2 hi = depth * vec2(floatFromOrdered(state.boundsMax.x), floatFromOrdered(state.boundsMax.y)) -
                    r4d.light.xy;
  precise vec2 size = hi - lo;
  float scale = max(max(max(abs(lo.x), abs(lo.y)), max(abs(hi.x), abs(hi.y))),
                    max(max(size.x, size.y), 1e-6));
  precise vec2 extent = max(size, vec2(1e-6 * scale));
  // Round-off tolerance: triangle boxes grow by it, so rounding only adds pairs.
  precise float tolerance = 1e-5 * scale;
  state.plane = vec4(depth, tolerance, 0.0, 0.0);
  // The quotient in double, then rounded to float: the correctly rounded float quotient the
  // CPU computed (double has more than 2 x 24 + 2 bits), where a float division may be
  // compiled into a reciprocal and a product.
  state.fb = vec4(lo, vec2(dvec2(r4d.sizes.xy) / dvec2(extent)));
}
