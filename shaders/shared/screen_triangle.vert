// One triangle covering the viewport (app/gl/screen_triangle.h): corners (-1,-1), (3,-1),
// (-1,3) in clip space from gl_VertexID 0, 1, 2; every texel centre lies inside it once.
void main() {
  vec2 corner = vec2(float((gl_VertexID & 1) << 2), float((gl_VertexID & 2) << 1)) - 1.0;
  gl_Position = vec4(corner, 0.0, 1.0);
}
