// Stage `receivers`: 1 where the visible surface belongs to a receiver-only object, else 0.
#include "stages/ground_truth/receivers/receivers_layout.h"
layout(location = RECEIVERS_FLAG_LOCATION) uniform float uReceiverOnly;
layout(location = 0) out vec4 outReceiver;
void main() { outReceiver = vec4(uReceiverOnly); }
