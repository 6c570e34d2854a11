// Grader self-test submission (stage 05c_wide_bvh), broken:
// primitive_order reversed in the wide tree, the leaves' ranges kept: they name other primitives.
#define WIDE_BVH_VARIANT(v) v.order_reversed = true
#include "wide_bvh_variant.h"
