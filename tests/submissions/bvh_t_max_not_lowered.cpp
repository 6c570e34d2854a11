// Grader self-test submission (stage 05_bvh): the reference traversal keeping the closest
// hit by comparison, but never lowering search.t_max. Correct answers (and, as the framework
// shades the primitive the traversal returns, a correct picture), more work; expected hint:
// "t_max not lowered after a hit".
// The reference file is included with its intersect_bvh renamed; the traversal is the shared
// one of bvh_submission_traversal.h with this submission's mistake.
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
  mistakes.t_max_not_lowered = true;
  return submission::traverse_bvh(bvh, ray, intersector, any_hit, stats, mistakes);
}

}  // namespace raylab
