// Grader self-test submission (stage 08_direct_light), hostile: direct_no_choice_probability (the
// light's sample not divided by the chance of choosing it: 1 / n of the light) with zero-mean noise
// on top wherever there are several lights, 200 times the estimate, so that the t-tests' standard
// error, taken from its own samples, would swallow the bias. The tests count no more variance than
// 4 times a correct estimator's, so this loses what its honest twin loses, and no more.
#define DIRECT_VARIANT(v) (v.divide_by_choice = false, v.noise_hides_bias = true)
#include "direct_variant.h"
