// Grader self-test submission (stage 05_bvh), hostile: bvh_prunes_only_at_leaves (every node's
// box tested, pruning only at leaves) with its work hidden as well as a liar can: it reports in
// stats.nodes_visited exactly the nodes on the paths from the root to the leaves it tested, the
// lower bound the grader checks. Nodes visited are counted in the stage server, so the grader
// does not score them (docs/instructors.md): the lie must gain nothing, so this scores exactly
// what its honest twin scores.
#define intersect_bvh reference_intersect_bvh
#include "../../solutions/05_bvh/bvh.cpp"
#undef intersect_bvh

#include "bvh_submission_traversal.h"

namespace raylab {

std::optional<BvhHit> intersect_bvh(const Bvh& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                    bool any_hit, BvhTraversalStats& stats);

std::optional<BvhHit> intersect_bvh(const Bvh& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                    bool any_hit, BvhTraversalStats& stats) {
  submission::TraversalMistakes mistakes;
  mistakes.prunes_only_at_leaves = true;
  return submission::traverse_bvh(bvh, ray, intersector, any_hit, stats, mistakes, submission::NodesReport::LowerBound);
}

}  // namespace raylab
