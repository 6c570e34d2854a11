// Grader self-test submission (stage 08_direct_light), broken: two mistakes of the estimator's own
// at once: its light sample not divided by the probability of choosing the light, and its own f =
// the albedo (1 / pi missing; lambertian_f is right). Neither alone explains the means (pi / 2 and
// pi / 4 of the direct light); the pair does, and both are named.
#define DIRECT_VARIANT(v) (v.divide_by_choice = false, v.f_is_albedo = true)
#include "direct_variant.h"
