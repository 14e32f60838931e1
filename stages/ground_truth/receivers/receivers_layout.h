// Locations of receivers.frag (C++: stages/ground_truth/receivers/receivers.cpp).
#define RECEIVERS_FLAG_LOCATION 0
