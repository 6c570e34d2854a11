// Grader self-test submission (stage 05_bvh): the traversal starts at bvh.nodes[0] without
// checking that the tree has nodes; on an empty tree (a scene without triangles) it reads past the
// end of an empty vector and crashes. Only the closest-hit test, which traverses an empty tree,
// is lost, with the hint to return before reading nodes[0].
#define BVH_SUBMISSION(mistakes, report) mistakes.empty_tree_not_checked = true
#include "bvh_submission.h"
