// Grader self-test submission (stage 05c_wide_bvh), broken:
// entry_distances[i] is where the ray leaves the box, not where it enters.
#define WIDE_BVH_VARIANT(v) v.entry_is_exit = true
#include "wide_bvh_variant.h"
