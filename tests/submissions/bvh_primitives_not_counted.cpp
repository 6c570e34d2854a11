// Grader self-test submission (stage 05_bvh): the reference traversal, but stats.primitives_tested
// never counts the calls of intersector.test (the contract: one per call). Correct hits and work;
// expected: only the work test fails, with the hint "stats.primitives_tested does not count".
#define BVH_SUBMISSION(mistakes, report) mistakes.primitives_not_counted = true
#include "bvh_submission.h"
