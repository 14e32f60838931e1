// Image units of hash.comp (C++: stages/shared_inputs/hash/hash.cpp).
#define HASH_SAMPLES_IMAGE 0
#define HASH_BITS_IMAGE 1
