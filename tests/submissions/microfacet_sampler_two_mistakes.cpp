// Grader self-test submission (stage 10_microfacet): half vectors sampled with two mistakes at
// once, tan(theta) = alpha' u / (1 - u) (the square root missing) with alpha' = alpha^2 (squared
// before the formula). The half vectors' test names both; the wi samples' test the half vectors
// they are built on.
#define MICROFACET_VARIANT(v) (v.half_vector_no_sqrt = true, v.half_vector_alpha_squared = true)
#include "microfacet_variant.h"
