// Grader self-test submission (stage 10_microfacet), broken: sample_ggx_half_vector returns its
// half vector below the surface (z negated). The reflected wi is the same, so only the half
// vector's own test sees it.
#define MICROFACET_VARIANT(v) v.half_vector_below = true
#include "microfacet_variant.h"
