// Locations of receivers.frag (C++: stages/ground_truth/receivers.cpp).
#define RECEIVERS_FLAG_LOCATION 0
