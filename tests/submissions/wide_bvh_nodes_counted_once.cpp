// Grader self-test submission (stage 05c_wide_bvh), broken: stats.nodes_visited is incremented once,
// before the traversal's loop instead of inside it, so every ray reports one node whatever it
// visited.
#define WIDE_BVH_VARIANT(v) v.nodes_counted_once = true
#include "wide_bvh_variant.h"
