// Grader self-test submission (stage 05_bvh): the traversal tests primitive_order[i] but returns
// i, the triangle's position in the leaf, as the hit's primitive. Every distance is right; the
// primitive is not (the renderer would shade another triangle's material and normal).
#define BVH_SUBMISSION(mistakes, report) mistakes.returns_leaf_position = true
#include "bvh_submission.h"
