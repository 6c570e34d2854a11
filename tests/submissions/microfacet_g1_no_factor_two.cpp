// Grader self-test submission (stage 10_microfacet), broken: Smith's G1 without the factor 2 of its
// numerator: 1/2 along the normal, where no microfacet is hidden and G1 is 1.
#define MICROFACET_VARIANT(v) v.g1_no_factor_two = true
#include "microfacet_variant.h"
