// Grader self-test submission (stage 08_direct_light), correct: the light chosen with probability
// proportional to its power (light_power) instead of uniformly, and divided by that probability.
// Expected: full marks.
#define DIRECT_VARIANT(v) v.lights_by_power = true
#include "direct_variant.h"
