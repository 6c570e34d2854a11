// Grader self-test submission (stage 10_microfacet): two mistakes at once in D, alpha squared
// before the formula (a "roughness" squared, as some engines do) and 1 / pi left out. The fitted
// model names both; f and the two densities, which are right but built on this D, are named as
// built on it (not blamed).
#define MICROFACET_VARIANT(v) (v.d_alpha_squared_first = true, v.d_no_inverse_pi = true)
#include "microfacet_variant.h"
