// A stage-05 self-test submission in two lines: the reference file (its builders; its own
// intersect_bvh renamed away) and, as intersect_bvh, the shared traversal of
// bvh_submission_traversal.h with the submission's mistakes. Before including this, define
//   #define BVH_SUBMISSION(mistakes, report) mistakes.far_child_first = true
// setting fields of submission::TraversalMistakes `mistakes` and, for the hostile ones, the
// submission::NodesReport `report` (comma-separated).
#define intersect_bvh reference_intersect_bvh
#include "../../solutions/05_bvh/bvh.cpp"
#undef intersect_bvh

#include "bvh_submission_traversal.h"

namespace raylab {

// Declared again: the header's declaration was renamed with the reference's definition.
std::optional<BvhHit> intersect_bvh(const Bvh& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                    bool any_hit, BvhTraversalStats& stats);

std::optional<BvhHit> intersect_bvh(const Bvh& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                    bool any_hit, BvhTraversalStats& stats) {
  submission::TraversalMistakes mistakes;
  submission::NodesReport report = submission::NodesReport::Honest;
  BVH_SUBMISSION(mistakes, report);
  return submission::traverse_bvh(bvh, ray, intersector, any_hit, stats, mistakes, report);
}

}  // namespace raylab
