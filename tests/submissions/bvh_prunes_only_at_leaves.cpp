// Grader self-test submission (stage 05_bvh): a traversal that tests every node's box but
// enters every inner node whatever its box says, and skips only the leaves whose box the ray
// misses (or enters beyond the closest hit). Its hits and the triangles it tests are the
// reference's; the extra box tests cost time but cannot be seen from outside the student's
// process, and it counts them honestly in stats.nodes_visited. Expected: full marks (the work
// test scores only what the grader observes itself, docs/instructors.md) and an unscored hint
// naming the box tests it could skip. It is the honest twin of hostile_bvh_reports_lower_bound.
#define BVH_SUBMISSION(mistakes, report) mistakes.prunes_only_at_leaves = true
#include "bvh_submission.h"
