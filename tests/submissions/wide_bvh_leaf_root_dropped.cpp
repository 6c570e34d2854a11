// Grader self-test submission (stage 05c_wide_bvh), broken:
// a binary tree of one leaf gives a wide root with no child (its primitives lost).
#define WIDE_BVH_VARIANT(v) v.leaf_root_dropped = true
#include "wide_bvh_variant.h"
