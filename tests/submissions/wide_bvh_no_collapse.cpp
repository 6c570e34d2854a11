// Grader self-test submission (stage 05c_wide_bvh): every wide node is one binary node with its two
// children. A valid Bvh4, and every answer right, but not wide: only CollapseIsWide loses.
#define WIDE_BVH_VARIANT(v) (v.no_collapse = true)
#include "wide_bvh_variant.h"
