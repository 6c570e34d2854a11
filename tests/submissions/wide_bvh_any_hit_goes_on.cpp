// Grader self-test submission (stage 05c_wide_bvh), broken: with any_hit, the traversal searches
// on for the closest hit instead of returning the first. Its answers are real hits, so only the
// check that any_hit returns at once fails (in AnyHitAgreesWithBruteForce).
#define WIDE_BVH_VARIANT(v) v.any_hit_goes_on = true
#include "wide_bvh_variant.h"
