// Grader self-test submission (stage 05c_wide_bvh): a correct implementation written another way: a
// plain loop over the four slots instead of SIMD, a collapse that takes both children's children
// (no surface areas), a traversal over a std::vector stack. Full marks.
#define WIDE_BVH_VARIANT(v) (v.two_levels = true)
#include "wide_bvh_variant.h"
