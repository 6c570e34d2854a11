// Grader self-test submission (stage 10_microfacet), broken: Smith's G1 with tan(theta) where the
// formula has tan^2(theta). Along the normal (tan 0) it is still 1.
#define MICROFACET_VARIANT(v) v.g1_tan_not_squared = true
#include "microfacet_variant.h"
