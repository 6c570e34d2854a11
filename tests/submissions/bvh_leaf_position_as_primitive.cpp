// Grader self-test submission (stage 05_bvh): the reference traversal testing primitive
// `i` (the position in the leaf's range) instead of primitive_order[i]. With the reference
// box test: wrong and missed hits, also on axis-aligned rays, and the hint must blame the
// traversal, never the box test (stage 04_box), which is right.
#define BVH_SUBMISSION(mistakes, report) mistakes.leaf_position_as_primitive = true
#include "bvh_submission.h"
