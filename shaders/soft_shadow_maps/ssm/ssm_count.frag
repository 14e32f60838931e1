// Counts overlapping primitives with additive blending.
layout(location = 0) out vec2 outCount;
void main() { outCount = vec2(1.0); }
