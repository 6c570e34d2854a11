// Grader self-test submission (stage 05c_wide_bvh), broken:
// unused slots get the box [0, 0], not empty_bvh4_node()'s (+inf, -inf).
#define WIDE_BVH_VARIANT(v) v.empty_slots_zero_boxes = true
#include "wide_bvh_variant.h"
