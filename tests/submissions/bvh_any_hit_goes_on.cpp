// Grader self-test submission (stage 05_bvh): with any_hit, the traversal searches on for the
// closest hit instead of returning the first. Its answers are real hits, so only the check that
// any_hit returns at once fails (in AnyHitAgreesWithBruteForce).
#define BVH_SUBMISSION(mistakes, report) mistakes.any_hit_goes_on = true
#include "bvh_submission.h"
