// Layout of stage `classify`'s pixel counts, read by C++ (stages/classify.cpp, checked with
// static_assert) and GLSL: a std430 storage buffer at CLASSIFY_COUNTS_BINDING holding one
// uint per class of classes.h (std430 uint arrays have stride 4, as in C++).
#define CLASSIFY_COUNTS_BINDING 2
#define CLASSIFY_CLASS_COUNT 5
struct ClassifyCounts {
  uint pixels[8];  // indexed by CLASS_*; 5..7 unused (padding to 32 bytes)
};
