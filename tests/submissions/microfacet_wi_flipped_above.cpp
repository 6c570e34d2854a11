// Grader self-test submission (stage 10_microfacet): a wi below the surface is mirrored above it
// instead of returned (the contract: return it, the framework then has no sample). The wi
// samples' half vectors no longer follow GGX's density from an oblique wo.
#define MICROFACET_VARIANT(v) (v.wi_flipped_above = true)
#include "microfacet_variant.h"
