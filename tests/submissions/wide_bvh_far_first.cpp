// Grader self-test submission (stage 05c_wide_bvh): the traversal visits the children farthest first
// and tests every box with the ray's own t_max, skipping nothing beyond the closest hit: right
// answers, too much work.
#define WIDE_BVH_VARIANT(v) (v.far_first_no_pruning = true)
#include "wide_bvh_variant.h"
