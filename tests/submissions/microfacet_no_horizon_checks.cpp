// Grader self-test submission (stage 10_microfacet), broken: no test of the surface anywhere: D, G1,
// f and both densities return their formula's value below the surface too, where the contract
// says 0 (h.z <= 0, z <= 0, wo or wi below).
#define MICROFACET_VARIANT(v) v.horizon_checks = false
#include "microfacet_variant.h"
