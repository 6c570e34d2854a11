// Grader self-test submission (stage 05_bvh), broken: any_hit stops at the first leaf whose box
// the ray hits and returns that leaf's first primitive, whether the ray hits it or not (a box hit
// taken for a primitive hit). Closest hits are right.
#define BVH_SUBMISSION(mistakes, report) mistakes.any_hit_at_leaf_box = true
#include "bvh_submission.h"
