// Grader self-test submission (stage 10_microfacet): the half vector's horizontal part normalised
// before it is scaled by sin(theta), which is 0 for u.x = 0 (a number the contract says can
// happen): normalize of a zero vector is NaN. Random numbers are almost never exactly 0; the
// edge inputs the sampler tests ask first are, so the half vectors' test and the wi test built on
// them fail, naming NaN.
#define MICROFACET_VARIANT(v) (v.azimuth_normalised = true)
#include "microfacet_variant.h"
