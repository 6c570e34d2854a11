// Grader self-test submission (stage 08_direct_light): one light chosen at random, but its sample
// not divided by the probability of choosing it: with n lights, 1 / n of the light.
#define DIRECT_VARIANT(v) v.divide_by_choice = false
#include "direct_variant.h"
