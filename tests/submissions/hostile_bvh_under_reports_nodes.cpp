// Grader self-test submission (stage 05_bvh), hostile: bvh_prunes_only_at_leaves (every node's
// box tested, pruning only at leaves) reporting one node visited per ray, fewer than the nodes
// above the leaves whose triangles the grader saw it test. A count the grader can prove false
// breaks the contract of stats (BvhTraversalStats) and loses DoesNoMoreWorkThanTheReference,
// although its honest twin keeps it.
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
  return submission::traverse_bvh(bvh, ray, intersector, any_hit, stats, mistakes, submission::NodesReport::One);
}

}  // namespace raylab
