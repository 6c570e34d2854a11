// Grader self-test submission (stage 05c_wide_bvh), broken:
// an empty binary tree gives one empty wide node instead of an empty Bvh4.
#define WIDE_BVH_VARIANT(v) v.empty_tree_gets_a_node = true
#include "wide_bvh_variant.h"
