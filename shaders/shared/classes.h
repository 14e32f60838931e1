// Pixel classes written by stage `classify` (thesis §3.6), read by C++ and GLSL.
#define CLASS_BACKGROUND 0
#define CLASS_LIT 1
#define CLASS_PENUMBRA 2
#define CLASS_UMBRA 3
#define CLASS_OUTSIDE 4
