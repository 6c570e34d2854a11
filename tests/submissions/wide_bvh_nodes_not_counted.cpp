// Grader self-test submission (stage 05c_wide_bvh), broken:
// stats.nodes_visited never incremented (the work it did goes unreported).
#define WIDE_BVH_VARIANT(v) v.nodes_not_counted = true
#include "wide_bvh_variant.h"
