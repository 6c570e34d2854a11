// Grader self-test submission (stage 05c_wide_bvh): stats.primitives_tested is never incremented
// (right answers, right work otherwise); the work test compares it with the tests the judge
// answered.
#define WIDE_BVH_VARIANT(v) (v.primitives_not_counted = true)
#include "wide_bvh_variant.h"
