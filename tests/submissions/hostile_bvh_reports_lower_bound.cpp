// Grader self-test submission (stage 05_bvh), hostile: bvh_prunes_only_at_leaves (every node's
// box tested, pruning only at leaves) with its work hidden as well as a liar can: it reports in
// stats.nodes_visited exactly the nodes on the paths from the root to the leaves it tested, the
// lower bound the grader checks. Nodes visited are counted in the stage server, so the grader
// does not score them (docs/instructors.md): the lie must gain nothing, so this scores exactly
// what its honest twin scores.
#define BVH_SUBMISSION(mistakes, report) (mistakes.prunes_only_at_leaves = true, report = submission::NodesReport::LowerBound)
#include "bvh_submission.h"
