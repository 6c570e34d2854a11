// Grader self-test submission (stage 05_bvh), hostile: bvh_prunes_only_at_leaves (every node's
// box tested, pruning only at leaves) reporting one node visited per ray, fewer than the nodes
// above the leaves whose triangles the grader saw it test. A count the grader can prove false
// breaks the contract of stats (BvhTraversalStats) and loses DoesNoMoreWorkThanTheReference,
// although its honest twin keeps it.
#define BVH_SUBMISSION(mistakes, report) (mistakes.prunes_only_at_leaves = true, report = submission::NodesReport::One)
#include "bvh_submission.h"
