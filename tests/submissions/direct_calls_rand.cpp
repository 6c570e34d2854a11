// Grader self-test submission (stage 08_direct_light): the light's point from rand(), not from
// sampler.get_2d(). Its estimates have the right mean, so only the test that asks for the same
// samples twice with the same seed fails (in EstimatorUnderQuadLight), naming rand().
#define DIRECT_VARIANT(v) v.own_random_numbers = true
#include "direct_variant.h"
