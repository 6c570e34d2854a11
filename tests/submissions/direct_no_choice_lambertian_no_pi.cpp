// Grader self-test submission (stage 08_direct_light), broken: lambertian_f without 1 / pi (its own
// test names it, and the estimator, which runs it through bsdf_f, is told to fix it first) and,
// besides, the estimator's light sample not divided by the probability of choosing the light,
// which the fit of the two together names too.
#define DIRECT_VARIANT(v) (v.lambertian_pi = false, v.divide_by_choice = false)
#include "direct_variant.h"
